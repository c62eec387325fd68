#include "solver/continuation_metric.h"
#include "twb/error_family.h"

#include <cmath>
#include <stdexcept>

namespace twb {

ContinuationMetric::ContinuationMetric(std::vector<double> weights, double parameter_scale)
    : omega_(std::move(weights)), parameter_scale_(parameter_scale) {
  if (!(parameter_scale_ > 0) || !std::isfinite(parameter_scale_))
    throw InternalError("ContinuationMetric: the parameter scale must be positive");
  double sum = 0.0;
  for (double& w : omega_) {
    if (!(w > 0) || !std::isfinite(w)) throw InternalError("ContinuationMetric: weights must be positive");
    w *= w;
    sum += w;
  }
  for (double& w : omega_) w /= sum;
}

ContinuationMetric ContinuationMetric::of(const SteadySystem& system, double parameter_scale,
                                          std::vector<double> weights) {
  if (weights.empty()) weights = system.step_weights();
  if (Index(weights.size()) != system.size())
    throw InternalError("ContinuationMetric: one weight per unknown");
  if (!(parameter_scale > 0)) parameter_scale = std::abs(system.parameter()) > 0 ? std::abs(system.parameter()) : 1.0;
  return ContinuationMetric(std::move(weights), parameter_scale);
}

double ContinuationMetric::state_dot(std::span<const double> a, std::span<const double> b) const {
  double s = 0.0;
  for (std::size_t k = 0; k < omega_.size(); ++k) s += omega_[k] * a[k] * b[k];
  return s;
}

double ContinuationMetric::dot(std::span<const double> a, std::span<const double> b) const {
  return state_dot(a, b) + a[omega_.size()] * b[omega_.size()];
}

double ContinuationMetric::state_norm(std::span<const double> a) const { return std::sqrt(state_dot(a, a)); }
double ContinuationMetric::norm(std::span<const double> a) const { return std::sqrt(dot(a, a)); }

}  // namespace twb
