#include "solver/bordered_system.h"
#include "twb/error_family.h"

#include <algorithm>
#include <stdexcept>

namespace twb {

BorderedSystem::BorderedSystem(SteadySystem& base, ContinuationMetric metric, std::string last_equation)
    : base_(base), metric_(std::move(metric)), matrix_(base.pattern()), last_equation_(std::move(last_equation)) {
  if (metric_.state_size() != base_.size()) throw InternalError("BorderedSystem: metric of another size");
}

std::vector<double> BorderedSystem::extend(std::span<const double> u, double lambda) const {
  std::vector<double> x(u.begin(), u.end());
  x.push_back(lambda / metric_.parameter_scale());
  return x;
}

void BorderedSystem::parameter_derivative(std::span<const double> x, std::span<double> derivative) const {
  std::fill(derivative.begin(), derivative.end(), 0.0);
  derivative[x.size() - 1] = -1.0;
}

std::vector<double> BorderedSystem::capacities() const {
  std::vector<double> c = base_.capacities();
  c.push_back(0.0);
  return c;
}

std::vector<double> BorderedSystem::step_weights() const {
  std::vector<double> w = base_.step_weights();
  w.push_back(1.0);
  return w;
}

std::string BorderedSystem::block_name(Index k) const {
  return k < base_.size() ? base_.block_name(k) : last_equation_;
}

std::string BorderedSystem::describe_row(Index k) const {
  return k < base_.size() ? base_.describe_row(k) : last_equation_;
}

}  // namespace twb
