#include "solver/relaxation_time.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>


#include "solver/sparse_lu.h"
#include "solver/sundials_context.h"
#include "twb/error_family.h"

namespace twb {

namespace {

double differential_max(const std::vector<double>& v, const std::vector<double>& capacities) {
  double m = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (capacities[k] > 0.0) m = std::max(m, std::abs(v[k]));
  return m;
}

}  // namespace

double slowest_relaxation_time(const SteadySystem& system, std::span<const double> u, int iterations) {
  const auto n = std::size_t(system.size());
  const std::vector<double> capacities = system.capacities();
  if (std::none_of(capacities.begin(), capacities.end(), [](double c) { return c > 0.0; }))
    throw InternalError("slowest_relaxation_time: no unknown has a capacity");
  const SparsePattern& p = system.pattern();
  std::vector<double> residual(n), jacobian(std::size_t(p.nnz()));
  system.evaluate(u, residual, jacobian);

  SparseLu lu(p);
  if (!lu.factor(jacobian)) throw SolverFailure("slowest_relaxation_time: the Jacobian is singular at the state", -1);

  // Start with every differential unknown displaced alike: the slowest mode of a
  // heated body is one-signed, so the start has a large component along it.
  std::vector<double> v(n), x(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = capacities[k] > 0.0 ? 1.0 : 0.0;
  double previous_growth = 0.0, growth = 0.0;
  for (int it = 0; it < std::max(iterations, 2); ++it) {
    for (std::size_t k = 0; k < n; ++k) x[k] = capacities[k] * v[k];
    lu.solve(x);
    previous_growth = growth;
    growth = differential_max(x, capacities) / differential_max(v, capacities);
    if (!std::isfinite(growth) || growth == 0.0) break;
    for (std::size_t k = 0; k < n; ++k) v[k] = x[k] / growth;
  }
  if (!std::isfinite(growth) || growth == 0.0)
    throw SolverFailure("slowest_relaxation_time: inverse iteration broke down", -1);
  // The geometric mean of the last two growth factors also converges when the two
  // slowest modes have equal |μ| and opposite signs (growth alternating).
  return std::sqrt(growth * previous_growth);
}

}  // namespace twb
