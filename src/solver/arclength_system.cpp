#include "solver/arclength_system.h"

#include <cmath>

#include "solver/sundials_context.h"

namespace twb {

ArclengthSystem::ArclengthSystem(SteadySystem& base, ContinuationMetric scaling)
    : BorderedSystem(base, std::move(scaling), "arclength") {
  const auto n = std::size_t(base.size());
  anchor_.assign(n + 1, 0.0);
  direction_.assign(n + 1, 0.0);
  direction_[n] = 1.0;
}

void ArclengthSystem::set_step(std::span<const double> anchor, std::span<const double> tangent, double step) {
  anchor_.assign(anchor.begin(), anchor.end());
  direction_.assign(tangent.begin(), tangent.end());
  set_parameter(step);
}

void ArclengthSystem::assemble(std::span<const double> x, std::span<const double> row, std::span<double> residual,
                               std::span<double> jacobian) const {
  SteadySystem& b = base();
  const auto n = std::size_t(b.size());
  const std::span<const double> u = x.first(n);
  b.set_parameter(lambda_of(x));
  std::vector<double> f(n), base_jac(jacobian.empty() ? 0 : std::size_t(b.pattern().nnz()));
  b.evaluate(u, f, base_jac);
  if (!residual.empty()) std::copy(f.begin(), f.end(), residual.begin());
  if (jacobian.empty()) return;
  std::vector<double> column(n), weighted_row(n);
  b.parameter_derivative(u, column);
  for (double& c : column) c *= metric().parameter_scale();
  const std::span<const double> omega = metric().state_weights();
  for (std::size_t k = 0; k < n; ++k) weighted_row[k] = omega[k] * row[k];
  matrix().assemble(base_jac, column, weighted_row, row[n], jacobian);
}

void ArclengthSystem::evaluate(std::span<const double> x, std::span<double> residual,
                               std::span<double> jacobian) const {
  assemble(x, direction_, residual, jacobian);
  std::vector<double> offset(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) offset[k] = x[k] - anchor_[k];
  residual[x.size() - 1] = metric().dot(direction_, offset) - parameter();
}

std::vector<double> ArclengthSystem::tangent(std::span<const double> x, std::span<const double> reference,
                                             const SparseLu* corrector_factors) {
  std::vector<double> t(x.size(), 0.0);
  t.back() = 1.0;
  if (corrector_factors && corrector_factors->factored()) {
    corrector_factors->solve(t);
  } else {
    std::vector<double> values(std::size_t(pattern().nnz()));
    assemble(x, reference, {}, values);
    if (!lu_) lu_ = std::make_unique<SparseLu>(pattern());
    if (!lu_->refactor(values))
      throw SolverFailure("the bordered tangent matrix is singular (a branch point rather than a fold?)", -1);
    lu_->solve(t);
  }
  // The last row made ⟨reference, t⟩ = 1 > 0: normalizing keeps the orientation.
  const double length = metric().norm(t);
  if (!std::isfinite(length) || length == 0.0) throw SolverFailure("the branch tangent is not finite", -1);
  for (double& c : t) c /= length;
  return t;
}

}  // namespace twb
