// The readers of the scene file's top-level sections, one per physical topic. Each
// validates its section completely and fills its part of the Scene; docs/scenes.md
// documents what they accept.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene_node.h"
#include "twb/input_error.h"
#include "twb/scene/scene.h"

namespace twb::scene_io {

// Roelands' law raises (1 + T/135 degC) to a fractional power: it is undefined at and
// below -135 degC.
inline constexpr double kRoelandsLowestTemperature = 138.15;  // K, -135 degC

Effects read_effects(const MapReader& scene);
// geometry, materials, surfaces (with the asperity parameters)
void read_bodies(const MapReader& scene, Scene& out);
// lubricant, operating, friction
void read_operation(const MapReader& scene, Scene& out);
// mesh, solver, study, output
void read_numerics(const MapReader& scene, Scene& out);
// geometry.washer.grooves, after the rest: they round the mesh to their edges and need
// the sliding film
void read_grooves(const MapReader& scene, Scene& out);
// A groove's width at `node`: a length at the washer's mean radius, or an angle (rad).
double groove_angle(const Node& node, double mean_radius);
// A map's or family's groove parameters (groove_count, groove_width, groove_depth): the
// scene has grooves, and every value, and every combination of the groove axes' values,
// places them (read after the grooves).
void check_groove_parameter(const MapReader& scene, const Scene& out);
// The nodes of a study's axes (study.parameter: a map, or a list of maps for a grid;
// study.family: a map), one per entry of Study::axes().
std::vector<MapReader> axis_nodes(const MapReader& scene);

// Why the scene refuses an input at `value`, if it does (the scene read again with it).
std::optional<InputError> refused(const Scene& out, const SceneInput& input, double value);
// A spread (a standard deviation) at `key` in `unit`, > 0: for a temperature an interval,
// not a point of the scale ("3 degC" is 3 K, not 276.15 K).
double read_spread(const MapReader& d, const char* key, const SiUnit& unit, std::string_view reason);
// A file a scene names: relative to the scene file's directory (to the working directory
// when an override named it); the path as resolved is noted, so that the scene read
// again from its tree finds the same file whichever file named it.
std::string named_file_path(const Node& node, std::string_view expected);
// Each entry of a study's map from input paths (`study.inputs`, `study.fit`) with the
// input it names; `none` says what an empty map lacks, `example` what it maps to;
// `not_taken(path)` is why the study refuses an input (empty: it takes it).
struct InputEntry {
  Node entry;
  SceneInput input;
};
std::vector<InputEntry> input_entries(const Node& map, const Scene& out, std::string_view none,
                                      std::string_view example,
                                      const std::function<std::string(const std::string&)>& not_taken);
// The study sections' reading once every input is known, each called only through its
// type's section (scene/studies/<type>_keys.cpp: read_after_inputs).
// A calibration study's data file, fitted inputs and measurement spreads (read once the
// scene's inputs are known).
void read_calibration(const MapReader& scene, Scene& out);
// study type duty_cycle: its schedule, in the scene or a CSV file it names (read_schedule.cpp).
void read_schedule(const MapReader& scene, Scene& out);
// The same into the settings of a cycle (a life's repeated one); the node `study.schedule`.
Node read_schedule_into(const MapReader& scene, Scene& out, DutyCycleSettings& s);
// A study marched in real time (`what`: "a duty cycle") needs the thermal effect and the
// Reynolds cavitation condition: refused at study.type otherwise.
void check_marched_in_real_time(const MapReader& study, const Scene& scene, std::string_view what);
// A reliability study's uncertain inputs: `study.inputs`, each an input of the scene with
// a distribution the scene accepts (read once the scene's inputs are known).
void read_uncertain_inputs(const MapReader& scene, Scene& out);

// The whole scene from the root of the (overridden) YAML tree.
Scene read_scene(const Node& root);

}  // namespace twb::scene_io
