// A load step on a running bearing, marched in the pseudo-time thermal transient
// (docs/physics.md sections 7-8) with its trajectory kept: the transient study, and past
// distress the runaway step marched to where it goes (the hot, contact-dominated
// branch). It never hangs: the march ends at a steady state, at the horizon, or where
// IDA cannot go on, and says which.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "twb/results/trajectory_table.h"
#include "solver/ida_transient.h"
#include "solver/kinsol_newton.h"

namespace twb {

struct StepMarch {
  bool settled = false;       // a steady state at the new load was reached (Newton-polished)
  bool started = false;       // a consistent state after the step was found (the march ran)
  std::vector<double> state;  // that state, or the last one integrated
  std::vector<TrajectorySample> trajectory;
  double time = 0.0;          // pseudo-time reached, s
  long newton_iterations = 0;
  long ida_steps = 0, ida_factorizations = 0;  // over IDA's restarts
  double wall_ms = 0.0;
  std::string message;        // how the march ended
};

// From start_state, steady at start_load, to new_load (the trajectory's and the state's
// load); the model's load is given back as it was.
// duration > 0 fixes the span of pseudo-time; 0 marches until the state settles, up to
// a horizon of many slowest relaxation times.
// start_time > 0 goes on with a step already under way: start_state is the trajectory's
// state at that time (not steady), and the march's samples follow on in time.
StepMarch march_load_step(BearingModel& model, std::span<const double> start_state, double start_load, double new_load,
                          const TransientSettings& settings, const NewtonSettings& newton, double duration = 0.0,
                          double start_time = 0.0);

}  // namespace twb
