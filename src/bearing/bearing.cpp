#include "twb/bearing.h"

#include <fmt/format.h>

#include "model/bearing_model.h"
#include "solver/steady_solver.h"
#include "study/study_runner.h"
#include "study/study_support.h"

namespace twb {

Bearing::Bearing(const Scene& scene) : model_(std::make_unique<BearingModel>(scene)) {}
Bearing::~Bearing() = default;
Bearing::Bearing(Bearing&&) noexcept = default;
Bearing& Bearing::operator=(Bearing&&) noexcept = default;

const Scene& Bearing::scene() const { return model_->scene(); }

std::vector<UnknownBlock> Bearing::unknowns() const { return model_->layout().blocks(); }

long Bearing::unknown_count() const { return long(model_->size()); }
long Bearing::jacobian_nonzeros() const { return long(model_->pattern().nnz()); }

SolvedState Bearing::solve(double load, double speed) {
  // The scene's load and speed are where a study starts; a point asked for here must
  // not depend on them, so both are set before either solve.
  const double old_load = model_->load(), old_speed = model_->speed();
  model_->set_load(load);
  model_->set_speed(speed);
  SteadySolver solver(*model_, newton_settings(model_->scene()));
  std::vector<double> u = state_;
  const SteadyReport rep = u.empty() ? solver.solve_cold(u) : solver.solve(u);
  if (!rep.converged) {
    model_->set_load(old_load);
    model_->set_speed(old_speed);
    throw SolverFailure(fmt::format("no steady state at {:.6g} N, {:.6g} rad/s: {}", load, speed, rep.message), -1);
  }
  state_ = u;
  SolvedState row = solved_state(*model_, u);
  row.converged = true;
  row.iterations = rep.iterations;
  row.residual = rep.residual_norm;
  row.wall_ms = rep.wall_ms;
  return row;
}

void Bearing::forget_state() { state_.clear(); }

StudyOutcome Bearing::run_study(const ProgressReport& progress, const RunOptions& options) {
  return twb::run_study(*model_, progress, options);
}

}  // namespace twb
