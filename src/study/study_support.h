// What every study needs from the scene and the clock: the scene's Newton settings,
// elapsed wall time, and a solved state as the studies record it.
#pragma once

#include <chrono>
#include <span>

#include "model/bearing_model.h"
#include "results/run_record.h"
#include "twb/results/states_table.h"
#include "twb/scene/scene.h"
#include "solver/kinsol_newton.h"
#include "study/searches/distress_search.h"

namespace twb {

inline NewtonSettings newton_settings(const Scene& s) {
  NewtonSettings n;
  n.residual_tolerance = s.solver.residual_tolerance;
  n.step_tolerance = s.solver.step_tolerance;
  n.max_iterations = s.solver.max_iterations;
  return n;
}

inline double elapsed_ms(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The reported quantities of state u at the model's load, and its fields on the films'
// grids when the scene asks for them (output.fields). Every study records its states
// here; the caller fills in how the state was solved.
inline SolvedState solved_state(const BearingModel& model, std::span<const double> u) {
  SolvedState row;
  row.state = model.describe(u);
  if (model.scene().output.fields) row.fields = model.fields(u);
  return row;
}

// A distress search's transients and IDA work, added to the study's (run.json).
inline void add_search_work(RunTimings& timings, const SearchCounts& counts) {
  timings.transients += counts.transients;
  timings.ida_steps += counts.ida_steps;
  timings.ida_factorizations += counts.ida_factorizations;
}

}  // namespace twb
