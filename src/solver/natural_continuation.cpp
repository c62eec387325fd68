#include "solver/natural_continuation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "solver/continuation_metric.h"
#include "solver/sparse_lu.h"
#include "solver/step_control.h"

namespace twb {

namespace {

// u_λ from J·u_λ = −F_λ at u and the system's current λ, with the factors lu holds.
std::vector<double> solve_sensitivity(const SteadySystem& system, const SparseLu& lu, std::span<const double> u) {
  std::vector<double> s(u.size());
  system.parameter_derivative(u, s);
  for (double& c : s) c = -c;
  lu.solve(s);
  return s;
}

// The same with J assembled at u and factored afresh; zeros if J is singular.
std::vector<double> sensitivity(const SteadySystem& system, SparseLu& lu, std::span<const double> u) {
  const auto n = u.size();
  std::vector<double> r(n), jac(std::size_t(system.pattern().nnz()));
  system.evaluate(u, r, jac);
  if (!lu.factor(jac)) return std::vector<double>(n, 0.0);
  return solve_sensitivity(system, lu, u);
}

std::vector<double> difference(std::span<const double> a, std::span<const double> b) {
  std::vector<double> d(a.size());
  for (std::size_t k = 0; k < a.size(); ++k) d[k] = a[k] - b[k];
  return d;
}

}  // namespace

NaturalReport continue_in_parameter(SteadySystem& system, std::vector<double>& u, double start, double target,
                                    const NaturalSettings& s, const BranchCallback& on_state) {
  return NaturalContinuation(system).continue_to(u, start, target, s, on_state);
}

NaturalContinuation::NaturalContinuation(SteadySystem& system) : system_(system), newton_(system) {}

NaturalReport NaturalContinuation::continue_to(std::vector<double>& u, double start, double target,
                                               const NaturalSettings& s, const BranchCallback& on_state) {
  SteadySystem& system = system_;
  const ParameterScope at_start(system, start);
  NaturalReport rep;
  const double interval = std::abs(target - start);
  const double direction = target >= start ? 1.0 : -1.0;
  rep.lambda = start;
  if (on_state && !on_state({0, u, start, 0.0, {}, 0})) {
    rep.message = "stopped by the caller at the start";
    return rep;
  }
  const ContinuationMetric metric = ContinuationMetric::of(system, 1.0, s.unknown_weights);
  const double min_step = s.min_step > 0 ? s.min_step : 1e-6 * interval;
  const double max_step = s.max_step > 0 ? s.max_step : 0.25 * interval;
  StepControl control(s.initial_step > 0 ? s.initial_step : interval / 20.0, min_step, max_step, s.growth,
                      s.easy_iterations);
  // One symbolic analysis serves the tangents and the corrector, and the first
  // tangent's fresh pivots serve the corrections' refactorizations.
  KinsolNewton& newton = newton_;
  SparseLu& lu = newton.factorization();

  // The state before u, and u_λ at u: the exact local slope, which judges every
  // correction. A secant carries the mean slope over the previous step, wrong by
  // O(u_λλ·Δλ_prev) however short the new step; after a long step towards a fold that
  // error alone exceeds the rejection threshold and the continuation stalls (on the
  // bearing, 1.2 N below the fold). The tangent's error shrinks with the step.
  std::vector<double> previous, slope;
  double previous_step = 0.0;
  if (!end_.empty() && start == end_lambda_ && u == end_) {
    // The leg starts where the last one ended: its slope holds here. (Each leg still
    // starts with the tangent predictor, as a fresh continuation does.)
    slope = slope_;
  } else {
    const NewtonForm form(system);  // every tangent in the corrector's form
    slope = sensitivity(system, lu, u);
  }
  const double first_slope = metric.state_norm(slope);
  while (rep.lambda != target) {
    const double step = control.step();
    // A step within rounding of the rest ends there: steps that add up to the interval
    // (its quarters, say) must not leave a sliver of 1e-14 whose correction is noise.
    const bool last = std::abs(target - rep.lambda) <= step * (1.0 + 1e-9);
    const double next = last ? target : rep.lambda + direction * step;
    const double dl = next - rep.lambda;
    std::vector<double> reference = u, trial = u;
    for (std::size_t k = 0; k < u.size(); ++k) reference[k] += dl * slope[k];
    if (s.predictor == Predictor::tangent || (s.predictor == Predictor::secant && previous.empty())) trial = reference;
    if (s.predictor == Predictor::secant && !previous.empty())
      for (std::size_t k = 0; k < u.size(); ++k) trial[k] += dl / previous_step * (u[k] - previous[k]);

    system.set_parameter(next);
    long iterations = 0;
    std::string failure;
    {
      const NewtonForm form(system);  // the corrector starts close
      failure = correct(newton, trial, s.newton, iterations, rep.corrector_iterations);
    }
    if (failure.empty()) {
      const double predicted = metric.state_norm(difference(reference, u));
      const double missed = metric.state_norm(difference(trial, reference));
      const double floor = std::sqrt(std::numeric_limits<double>::epsilon()) * (1.0 + metric.state_norm(u));
      if (missed > s.max_prediction_error * predicted + floor)
        failure = fmt::format("the corrected state lies {:.3g} from the tangent's prediction, more than {} of the "
                              "predicted change {:.3g}: the step outran the branch's curvature or jumped to another branch",
                              missed, s.max_prediction_error, predicted);
      else if (!previous.empty() && metric.state_dot(difference(trial, u), difference(u, previous)) < 0)
        failure = "the state moved against the branch's direction of travel: a jump to another branch?";
    }
    if (!failure.empty()) {
      ++rep.rejected;
      rep.last_rejection = fmt::format("Δλ = {:.3g} from λ = {:.10g}: {}", dl, rep.lambda, failure);
      system.set_parameter(rep.lambda);
      if (!control.reject()) {
        rep.message = fmt::format(
            "no steady state found beyond λ = {:.10g} with a step of at least {:.3g} (last attempt: {}). Since the "
            "start |du/dλ| grew {:.3g}-fold; a steep growth means the branch turns back at a fold near λ = {:.10g}, "
            "which only pseudo-arclength continuation can pass",
            rep.lambda, min_step, failure, rep.sensitivity_growth, rep.lambda);
        break;
      }
      continue;
    }
    previous = std::move(u);
    u = std::move(trial);
    previous_step = dl;
    rep.lambda = next;
    ++rep.accepted;
    // The corrector's last factors are J at its last Newton point, one step δ from u:
    // the step that brought F below the tolerance, Newton's shortest. They give u_λ to
    // O(‖δ‖), far inside what the prediction test tolerates (half the predicted change);
    // a fresh assembly and full factorization would cost more than a corrector
    // iteration. A correction with no iteration left no factors of its own. Both are
    // in the corrector's form, whose branch, and so whose tangent, is the system's.
    {
      const NewtonForm form(system);
      slope = iterations > 0 && lu.factored() ? solve_sensitivity(system, lu, u) : sensitivity(system, lu, u);
    }
    rep.sensitivity_growth = metric.state_norm(slope) / first_slope;
    control.accept(iterations);
    if (on_state && !on_state({rep.accepted, u, rep.lambda, 0.0, {}, iterations, lu.factored() ? &lu : nullptr})) {
      rep.message = fmt::format("stopped by the caller at λ = {:.10g}", rep.lambda);
      break;
    }
  }
  rep.reached_target = rep.lambda == target;
  end_ = u;
  end_lambda_ = rep.lambda;
  slope_ = slope;
  return rep;
}

}  // namespace twb
