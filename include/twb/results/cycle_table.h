// A duty cycle's events (study type duty_cycle, docs/physics.md section 19),
// cycle_events.csv: what happened along the cycle whose trajectory is trajectory.csv
// (trajectory_table.h): each failure criterion's crossing and recovery, the
// thermo-viscous runaway and its end, the cycle's worst moment and its end,
//   t_s, event, criterion, load_N, speed_rad_s, ambient_C, tilt_rad, margin,
//   failure_load_N, failure_criterion
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "twb/model/operating_limits.h"
#include "twb/results/distress_table.h"
#include "twb/results/result_table.h"

namespace twb {

struct CycleEvent {
  double time = 0.0;
  // "crossing" (a criterion's margin reaches zero, `criterion` says which), "recovery"
  // (back within it), "runaway" (the thermo-viscous runaway), "settled" (the runaway is
  // over: the slow thermal mode stable again, on the hot branch or back on the cool one),
  // "worst" (the least margin of the cycle, with the failure load at that moment's speed,
  // ambient and tilt), "rest" and "resume" (the washer unloaded at rest held, and balanced
  // again: docs/physics.md section 19), "end".
  std::string event;
  std::optional<LimitKind> criterion;
  double load = 0.0, speed = 0.0, ambient = 0.0, tilt = 0.0;
  std::optional<double> margin;                      // as trajectory.csv's least_margin
  std::optional<double> failure_load;                // N, "worst": W_fail at that moment
  std::optional<FailureCriterion> failure_criterion;
};

// The heat over a duty cycle (J, docs/physics.md section 19): generated in the films,
// conducted to the ambient, carried off by the oil (with convection), and stored in the
// bodies (their heat content at the end less at the start). generated = to_ambient +
// carried + stored to the integrator's tolerance.
struct CycleHeat {
  double generated = 0.0, to_ambient = 0.0, carried = 0.0, stored = 0.0;
  double error() const { return generated - to_ambient - carried - stored; }
};

ResultTable cycle_events_table(const std::vector<CycleEvent>& events);

}  // namespace twb
