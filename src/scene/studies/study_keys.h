// The keys more than one study type reads and writes (scene/studies/<type>_keys.cpp are
// their users): load ranges and grids, speeds, map axes, the bracket, the error bar.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "scene/scene_node.h"
#include "scene/scene_text.h"
#include "twb/scene/scene.h"

namespace twb::scene_io {

// load_start < load_end; `end_relation` says what lies between them in the message.
void read_load_range(const MapReader& study, LoadRange& loads, std::string_view end_relation);
// A dimensionless study key that is a number in `range` or `none` (0), left at `value`
// where absent.
void read_number_or_none(const MapReader& study, std::string_view key, const Range& range, double& value);
// study.tolerance: a relative accuracy ("1 %", 0.01) or none; refused beside
// error_estimate: none.
void read_tolerance(const MapReader& study, ErrorBarSettings& bars);
double read_bracket_width(const MapReader& study, double fallback);
// The scene path (or, for the roughness, every path under it) a named parameter sets.
std::string_view set_by(MapParameter p);
// A map's or sweep's axes besides the speed (`parameter`: one map, or a list of them for
// a grid), or a distress curve's family (`family`: one map).
void read_map_axes(const MapReader& study, std::vector<MapAxis>& axes, const Scene& scene,
                   const char* key = "parameter");
// Whether a speed was written in revolutions per minute.
bool given_in_rpm(const Node& speed);
// The speeds, and whether every one was written in rpm.
void read_speeds(const MapReader& study, std::vector<double>& speeds, bool& in_rpm);
// A load grid (load_sweep, sliding_choice): the range, its number of loads, the speeds.
void read_load_grid(const MapReader& study, Scene& out, LoadGrid& grid);
// every_state is for sweeps' states: refused for a point and a distress curve.
void refuse_every_state(const MapReader& study, const ErrorBarSettings& bars, const char* type);
// The nodes of a study's axes (its parameter's or family's maps, in order).
std::vector<MapReader> axis_nodes_of(const MapReader& study);

void write_load_range(SceneText& w, const LoadRange& loads);
void write_speeds(SceneText& w, std::span<const double> speeds);
// The axes under `key` (parameter, family): one as a map, a grid as a list; none: nothing.
void write_axes(SceneText& w, std::span<const MapAxis> axes, const char* key);
// A load grid as read_load_grid reads it, with its map's axes where it has them.
void write_load_grid(SceneText& w, const LoadGrid& grid, std::span<const MapAxis> axes = {});
void write_error_estimate(SceneText& w, const ErrorBarSettings& bars);
// The tolerance, where an error bar is asked for.
void write_tolerance(SceneText& w, const ErrorBarSettings& bars);
// A cycle's schedule, every point with every field (the resolved scene needs no schedule
// file).
void write_schedule(SceneText& w, const DutyCycleSettings& cycle);

}  // namespace twb::scene_io
