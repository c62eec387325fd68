#include "solver/arclength_continuation.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "solver/arclength_system.h"
#include "solver/step_control.h"
#include "twb/error_family.h"

namespace twb {

ArclengthReport continue_by_arclength(SteadySystem& system, std::span<const double> u0, double lambda0,
                                      const ArclengthSettings& s, const BranchCallback& on_point) {
  const ParameterScope at_start(system, lambda0);
  ArclengthReport rep;
  const auto n = std::size_t(system.size());
  ArclengthSystem arc(system, ContinuationMetric::of(system, s.parameter_scale, s.unknown_weights));
  const ContinuationMetric& metric = arc.metric();
  rep.u.assign(u0.begin(), u0.end());
  rep.lambda = system.parameter();
  {
    std::vector<double> r(n);
    system.evaluate(u0, r, {});
    if (!(max_norm(r) <= s.newton.residual_tolerance)) {
      rep.message = fmt::format("the start is not a steady state: residual {:.3g} above the tolerance {:.3g}",
                                max_norm(r), s.newton.residual_tolerance);
      return rep;
    }
  }
  std::vector<double> x = arc.extend(u0, rep.lambda), t;
  {
    std::vector<double> along_lambda(n + 1, 0.0);
    along_lambda[n] = s.direction >= 0 ? 1.0 : -1.0;
    try {
      t = arc.tangent(x, along_lambda);
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      rep.message = std::string("no tangent at the start: ") + e.what();
      return rep;
    }
  }
  if (on_point && !on_point({0, u0, rep.lambda, 0.0, t, 0})) {
    rep.stop = ArclengthReport::Stop::caller;
    rep.message = "stopped by the caller at the start";
    return rep;
  }

  KinsolNewton newton(arc);
  const double min_cos = std::cos(s.max_turn);
  StepControl control(s.initial_step, s.min_step, s.max_step, s.growth, s.easy_iterations);
  rep.stop = ArclengthReport::Stop::max_points;
  rep.message = "reached the largest number of states";
  while (rep.accepted < s.max_points) {
    const double step = control.step();
    arc.set_step(x, t, step);
    std::vector<double> trial(n + 1), next_t;
    for (std::size_t k = 0; k <= n; ++k) trial[k] = x[k] + step * t[k];
    const std::vector<double> predicted = trial;
    long iterations = 0;
    std::string failure = correct(newton, trial, s.newton, iterations, rep.corrector_iterations);
    if (failure.empty()) {
      std::vector<double> correction(n + 1);
      for (std::size_t k = 0; k <= n; ++k) correction[k] = trial[k] - predicted[k];
      try {
        // The corrector's last factors hold the bordered Jacobian with t as its last row.
        next_t = arc.tangent(trial, t, iterations > 0 ? &newton.factorization() : nullptr);
      } catch (const InternalError&) {
        throw;  // a bug: no fallback may hide it
      } catch (const std::exception& e) {
        failure = e.what();
      }
      if (failure.empty() && metric.norm(correction) > s.max_correction * step)
        failure = fmt::format("the correction {:.3g} exceeds {} of the step", metric.norm(correction), s.max_correction);
      else if (failure.empty() && metric.dot(t, next_t) < min_cos)
        failure = fmt::format("the tangent turned by {:.3g} rad", std::acos(std::clamp(metric.dot(t, next_t), -1.0, 1.0)));
    }
    if (!failure.empty()) {
      ++rep.rejected;
      rep.last_rejection = fmt::format("Δs = {:.3g} from λ = {:.10g}: {}", step, rep.lambda, failure);
      if (!control.reject()) {
        rep.stop = ArclengthReport::Stop::min_step;
        rep.message = fmt::format("no step of at least {:.3g} along the branch from λ = {:.10g} (last attempt: {})",
                                  s.min_step, rep.lambda, failure);
        break;
      }
      continue;
    }
    if (s.locate_folds && t[n] * next_t[n] < 0) {
      rep.folds.push_back(locate_fold(system, metric, {x, t, trial, next_t, step}, s.newton, s.fold));
    }
    x = std::move(trial);
    t = std::move(next_t);
    ++rep.accepted;
    rep.arclength += step;
    rep.lambda = arc.lambda_of(x);
    rep.u.assign(x.begin(), x.begin() + std::ptrdiff_t(n));
    control.accept(iterations);
    system.set_parameter(rep.lambda);  // the callback's contract (branch_point.h)
    if (on_point && !on_point({rep.accepted, rep.u, rep.lambda, rep.arclength, t, iterations})) {
      rep.stop = ArclengthReport::Stop::caller;
      rep.message = fmt::format("stopped by the caller at λ = {:.10g}", rep.lambda);
      break;
    }
    if (rep.lambda < s.lambda_min || rep.lambda > s.lambda_max) {
      rep.stop = ArclengthReport::Stop::parameter_bound;
      rep.message = fmt::format("left [{:.6g}, {:.6g}] at λ = {:.10g}", s.lambda_min, s.lambda_max, rep.lambda);
      break;
    }
  }
  return rep;
}

}  // namespace twb
