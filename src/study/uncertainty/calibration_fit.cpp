// The calibration's step 2, the fit (calibration_steps.h).
#include "study/uncertainty/calibration_steps.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "twb/scene/scene_inputs.h"
#include "twb/scene/scene_loader.h"

namespace twb {

namespace {

class ProgressLines final : public ceres::IterationCallback {
 public:
  explicit ProgressLines(const ProgressReport& progress) : progress_(progress) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (progress_)
      progress_(fmt::format("calibration: iteration {}, cost {:.6g} ({}){}", s.iteration, s.cost,
                            s.step_is_successful ? "step taken" : "step refused",
                            s.iteration == 0 ? "" : fmt::format(", trust region {:.3g}", s.trust_region_radius)));
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const ProgressReport& progress_;
};

ceres::Solver::Options fit_options(int iterations) {
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = iterations;
  // The first step within about the inputs' own size (scaled by their start), not
  // Ceres' default of 1e4 of it: a bearing far from its start may have no cool state.
  options.initial_trust_region_radius = 1.0;
  // No projected line search after each bounded step: its extra evaluations (each a
  // steady solve at every point) cost half the fit, and the bounds hold without it (the
  // step is projected onto them).
  options.max_num_line_search_step_size_iterations = 0;
  // The predictions are accurate to about 1e-8 relative (the solver's tolerance, the
  // derivatives' second-order differences): the fit is converged when a step changes
  // the cost by less than 1e-10 of itself or the scaled inputs by less than 1e-8.
  options.function_tolerance = 1e-10;
  options.parameter_tolerance = 1e-8;
  options.gradient_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;  // the points are spread over threads by the response itself
  return options;
}

}  // namespace

bool CalibrationSteps::fit() {
  // The inputs scaled by their start (or their range, where the start is zero), so that
  // Levenberg–Marquardt's trust region and tolerances see numbers of order one.
  scale_.resize(n_);
  x_.resize(n_);
  for (std::size_t j = 0; j < n_; ++j) {
    const FittedInput& f = study_.fitted[j];
    // (at least a thousandth of the range: a start of nearly zero would make its bounds
    // remote in the scaled input)
    scale_[j] = std::max(std::abs(f.start), 1e-3 * (f.upper - f.lower));
    x_[j] = f.start / scale_[j];
  }
  response_.emplace(bearing_scene(scene_), study_.fitted,
                    study_.measurements, threads_);
  cost_ = new MeasurementsCost(*response_, readings_, scale_, study_.fitted);
  problem_.AddResidualBlock(cost_, nullptr, x_.data());
  for (std::size_t j = 0; j < n_; ++j) {
    problem_.SetParameterLowerBound(x_.data(), int(j), study_.fitted[j].lower / scale_[j]);
    problem_.SetParameterUpperBound(x_.data(), int(j), study_.fitted[j].upper / scale_[j]);
  }

  // The start's predictions, for the report and a clear failure before any step.
  residuals_.resize(m_);
  {
    const double* block[] = {x_.data()};
    if (!cost_->Evaluate(block, residuals_.data(), nullptr)) {
      out_.solver_failed = true;
      out_.message = "calibration: the start is not a state of the bearing: " + cost_->failure;
      return false;
    }
  }
  at_start_ = cost_->last;

  ceres::Solver::Options options = fit_options(study_.fit_iterations);
  ProgressLines lines(progress_);
  options.callbacks.push_back(&lines);
  ceres::Solve(options, &problem_, &summary_);
  if (!summary_.IsSolutionUsable()) {
    out_.solver_failed = true;
    out_.message = fmt::format("calibration: no usable fit ({}){}", summary_.message,
                               cost_->failure.empty() ? "" : ": " + cost_->failure);
    return false;
  }

  // The fit's predictions and Jacobian.
  jacobian_.resize(m_ * n_);
  const double* block[] = {x_.data()};
  double* jac[] = {jacobian_.data()};
  if (!cost_->Evaluate(block, residuals_.data(), jac)) {
    out_.solver_failed = true;
    out_.message = "calibration: the fit is not a state of the bearing: " + cost_->failure;
    return false;
  }
  return true;
}

}  // namespace twb
