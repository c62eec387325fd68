// Where a duty cycle ended, to go on from there (twb run --continue-from DIR; docs/scenes.md,
// duty_cycle): cycle_end_state.json in its results directory holds the time, the
// schedule's inputs there, every unknown of the bearing's state (doubles bit for bit) and
// the bearing they belong to (the resolved scene without its study and output sections and
// the inputs a schedule sets, which a continued cycle may change).
#pragma once

#include <string>
#include <vector>

namespace twb {

struct CycleState {
  double time = 0.0;  // s
  double load = 0.0, speed = 0.0, ambient = 0.0, tilt = 0.0;  // N, rad/s, K, rad
  std::vector<double> unknowns;
  std::string bearing;  // bearing_of(the resolved scene)
};

// The resolved scene's text (describe_scene) without its study and output sections and
// the schedule's inputs (operating.load, .speed, .ambient, geometry.gear.tilt): what a
// state's unknowns mean.
std::string bearing_of(const std::string& resolved_scene);

std::string cycle_state_json(const CycleState& state);
// std::invalid_argument naming `path` and what is wrong with it (not there, not JSON, a
// field missing or of the wrong kind).
CycleState read_cycle_state(const std::string& path);
// The same from the file's text (twb.run's continue_from); `where` names it in errors.
CycleState cycle_state_of(const std::string& json, const std::string& where);

}  // namespace twb
