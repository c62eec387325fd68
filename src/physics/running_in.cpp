#include "physics/running_in.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace twb {
namespace {

double density(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * std::numbers::pi); }
double upper_tail(double x) { return 0.5 * std::erfc(x / std::numbers::sqrt2); }  // Q
double lower_tail(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }  // Φ

}  // namespace

double truncated_depth(double cut) { return density(cut) - cut * upper_tail(cut); }

// [W6] with τ²·Q − (τ·Q − φ)² written τ²·Q·Φ + 2τ·Q·φ − φ²: for a cut far below the
// mean the terms of [W6] as stated, of size τ², cancel to a variance of 2φ/|τ|³; these
// cancel by 1/τ⁴ only (4 digits at τ = −8), each term with its tail's relative precision.
double truncated_variance(double cut) {
  const double q = upper_tail(cut), p = lower_tail(cut), f = density(cut);
  return p - cut * f + cut * cut * q * p + 2.0 * cut * q * f - f * f;
}

// [W5] is decreasing and convex in τ (its second derivative is φ): Newton from the left
// of the root, where [W5] is above the depth, climbs to it monotonically. From
// τ = −depth − 1, where [W5] exceeds the depth by about one.
double cut_for_depth(double depth) {
  if (!(depth > truncated_depth(RunningIn::kHighestCut))) return RunningIn::kHighestCut;
  double cut = -depth - 1.0;
  for (int k = 0; k < 200; ++k) {
    const double step = (truncated_depth(cut) - depth) / upper_tail(cut);  // −f/f', f' = −Q
    cut += step;
    if (std::abs(step) <= 1e-15 * std::max(1.0, std::abs(cut))) return std::min(cut, RunningIn::kHighestCut);
  }
  return std::min(cut, RunningIn::kHighestCut);
}

RunningIn::RunningIn(double rq_new, std::optional<double> rq_run_in) : rq_new_(rq_new), rq_run_in_(rq_run_in) {
  if (!(rq_new > 0.0)) throw std::invalid_argument(fmt::format("RunningIn: Rq {} is not positive", rq_new));
  if (rq_run_in && !(*rq_run_in > 0.0 && *rq_run_in <= rq_new))
    throw std::invalid_argument(
        fmt::format("RunningIn: the run-in Rq {} is not within (0, Rq new = {}]", *rq_run_in, rq_new));
  if (!rq_run_in) return;
  // The cut where [W6] reaches (σ_run-in/σ0)²: [W6] rises with τ from 0 to 1, so by
  // bisection in τ over [−40, kHighestCut] (at −40 [W6] is below 1e-300).
  const double target = (*rq_run_in / rq_new) * (*rq_run_in / rq_new);
  if (target >= truncated_variance(kHighestCut)) {
    run_in_depth_ = 0.0;
    return;
  }
  double low = -40.0, high = kHighestCut;
  for (int k = 0; k < 200 && high - low > 1e-14 * std::max(1.0, std::abs(high)); ++k) {
    const double mid = 0.5 * (low + high);
    (truncated_variance(mid) < target ? low : high) = mid;
  }
  run_in_depth_ = rq_new * truncated_depth(0.5 * (low + high));
}

ValueSlope RunningIn::rq(double depth) const {
  if (run_in_depth_ && depth >= *run_in_depth_) return {*rq_run_in_, 0.0};
  if (!run_in_depth_) return {rq_new_, 0.0};
  const double cut = cut_for_depth(depth / rq_new_);
  const double share = std::sqrt(truncated_variance(cut));
  return {rq_new_ * share, -(cut * lower_tail(cut) + density(cut)) / share};
}

}  // namespace twb
