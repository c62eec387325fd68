#include "study/searches/operating_point.h"

#include <fmt/format.h>

#include "study/study_support.h"

namespace twb {

SolvedState recorded_state(const BearingModel& model, std::span<const double> u, const SteadyReport& rep) {
  SolvedState row = solved_state(model, u);
  row.converged = rep.converged;
  row.iterations = rep.iterations;
  row.residual = rep.residual_norm;
  row.wall_ms = rep.wall_ms;
  return row;
}

bool solve_operating_point(BearingModel& model, StudyOutcome& out, std::vector<double>& u) {
  SteadySolver solver(model, newton_settings(model.scene()));
  const SteadyReport rep = solver.solve_cold(u);
  out.timings.newton_iterations += rep.iterations;
  out.timings.jacobian_evaluations += rep.jacobian_evaluations;
  if (!rep.converged) {
    out.solver_failed = true;
    out.message = fmt::format("no steady state at {:.6g} N: {}", model.load(), rep.message);
    return false;
  }
  out.states.push_back(recorded_state(model, u, rep));
  return true;
}

}  // namespace twb
