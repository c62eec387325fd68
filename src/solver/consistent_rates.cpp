#include "solver/consistent_rates.h"

#include <fmt/format.h>

#include "twb/error_family.h"

namespace twb {

ConsistentRates::ConsistentRates(const SteadySystem& system, std::span<const double> y,
                                 const std::vector<double>& capacities, const std::vector<char>& differential,
                                 double reference_rate)
    : system_(system),
      held_(y.begin(), y.end()),
      capacities_(capacities),
      differential_(differential),
      reference_rate_(reference_rate),
      y_(y.size()),
      rate_(y.size()),
      scratch_(y.size()) {
  const SparsePattern& p = system_.pattern();
  for (Index k = 0; k < system_.size(); ++k) {
    diagonal_.push_back(p.find(k, k));
    if (capacities_[std::size_t(k)] > 0.0 && diagonal_.back() < 0)
      throw InternalError(fmt::format("ConsistentRates: row {} has a capacity and no diagonal entry", k));
  }
}

std::vector<double> ConsistentRates::unknowns_of(std::span<const double> y, std::span<const double> rate) const {
  std::vector<double> z(y.size());
  for (std::size_t k = 0; k < z.size(); ++k) z[k] = differential_[k] ? rate[k] : y[k];
  return z;
}

void ConsistentRates::state_of(std::span<const double> z, std::vector<double>& y, std::vector<double>& rate) const {
  y.resize(z.size());
  rate.resize(z.size());
  for (std::size_t k = 0; k < z.size(); ++k) {
    y[k] = differential_[k] ? held_[k] : z[k];
    rate[k] = differential_[k] ? z[k] : 0.0;
  }
}

void ConsistentRates::evaluate(std::span<const double> z, std::span<double> residual,
                               std::span<double> jacobian) const {
  state_of(z, y_, rate_);
  // With c_j = 0 the system's matrix is ∂F/∂y; with c_j = 1 it is ∂F/∂y + ∂F/∂y', so
  // their difference is ∂F/∂y' (nonzero only on the columns of the rates it reads).
  system_.evaluate_in_time(y_, rate_, 0.0, residual, jacobian);
  if (!jacobian.empty()) {
    matrix_at_unit_cj_.resize(jacobian.size());
    system_.evaluate_in_time(y_, rate_, 1.0, scratch_, matrix_at_unit_cj_);
    const SparsePattern& p = system_.pattern();
    for (Index r = 0; r < p.rows; ++r)
      for (Index e = p.row_start[std::size_t(r)]; e < p.row_start[std::size_t(r + 1)]; ++e) {
        const std::size_t c = std::size_t(p.column[std::size_t(e)]);
        if (differential_[c]) jacobian[std::size_t(e)] = matrix_at_unit_cj_[std::size_t(e)] - jacobian[std::size_t(e)];
      }
  }
  for (std::size_t k = 0; k < rate_.size(); ++k) {
    const double c = capacities_[k];
    if (c <= 0.0) continue;
    residual[k] += c * (rate_[k] + reference_rate_);
    if (!jacobian.empty()) jacobian[std::size_t(diagonal_[k])] += c;
  }
}

std::vector<double> ConsistentRates::step_weights() const {
  std::vector<double> w = system_.step_weights();
  for (std::size_t k = 0; k < w.size(); ++k)
    if (differential_[k]) w[k] = 1e-3;
  return w;
}

void ConsistentRates::set_parameter(double) {
  throw InternalError("ConsistentRates: the start has no parameter to set");
}

void ConsistentRates::parameter_derivative(std::span<const double>, std::span<double>) const {
  throw InternalError("ConsistentRates: the start has no parameter derivative");
}

}  // namespace twb
