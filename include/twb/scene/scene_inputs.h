// Every continuous input of a scene as a parameter addressed by its path in the scene
// file (docs/physics.md section 16): "geometry.gear.tilt", "surfaces.washer.Rq",
// "lubricant.viscosity.kv40", "operating.speed". A scene with inputs changed is the
// scene read again with them as overrides, so it is validated exactly like the file and
// everything derived from an input (a data sheet's viscosity fit, the summits of a
// roughness) follows it.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "twb/scene/scene.h"

namespace twb {

// Whether a path lies in the bearing's sections (geometry, materials, surfaces,
// lubricant, limits, operating, friction) and outside lists: where inputs are.
bool is_bearing_input_path(std::string_view path);

// Why an input moves the bearing by steps only, or empty where it moves it smoothly: the
// grooves' width, their dam's radius and the lands' inlet fraction are placed on the
// grid's cells and node lines (docs/physics.md section 14), so between two placements
// nothing changes and across one the answer jumps. They have no derivative: no
// sensitivity, FORM gradient, calibration or followed map can take them (a searched map
// can).
std::string stepwise_input(std::string_view path);

// The input at `path`: as the scene file writes it (Scene::inputs), else the default the
// scene resolved to (describe_scene), e.g. a material's thermal expansion the file leaves
// out. std::invalid_argument, saying which inputs there are, for a path that names none.
SceneInput scene_input(const Scene& scene, const std::string& path);

// The scene read again from Scene::written with each (path, SI value) set. InputError
// (input_error.h) where a value is out of its range, naming the override. keep_study:
// the scene's own study kept as it is, not read and checked again (a grid's combination:
// reading a map's study tries every value of its axes).
Scene with_inputs(const Scene& scene, std::span<const std::pair<std::string, double>> values,
                  bool keep_study = false);

// The scene read again from Scene::written as a point study: the bearing alone, whose
// copies at other inputs read it again without a study to check round the moved inputs.
// Both keep the scene's worn washer (Scene::worn).
Scene bearing_scene(const Scene& scene);

// The override text that sets an input: "geometry.gear.tilt=0.001 rad".
std::string input_override(const std::string& path, double value, std::string_view unit);

}  // namespace twb
