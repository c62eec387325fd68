#include "solver/fold_system.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/kinsol_newton.h"
#include "twb/error_family.h"

namespace twb {

FoldSystem::FoldSystem(SteadySystem& base, ContinuationMetric scaling, std::span<const double> parameter_direction,
                       std::span<const double> state_tangent)
    : BorderedSystem(base, std::move(scaling), "fold test function") {
  const auto n = std::size_t(base.size());
  if (parameter_direction.size() != n || state_tangent.size() < n)
    throw InternalError("FoldSystem: borders of another size");
  const double b_size = max_norm(parameter_direction), t_size = metric().state_norm(state_tangent.first(n));
  if (!(b_size > 0) || !(t_size > 0) || !std::isfinite(b_size) || !std::isfinite(t_size))
    throw InternalError("FoldSystem: zero or non-finite borders");
  b_.resize(n);
  c_.resize(n);
  const std::span<const double> omega = metric().state_weights();
  for (std::size_t k = 0; k < n; ++k) {
    b_[k] = parameter_direction[k] / b_size;
    c_[k] = omega[k] * state_tangent[k] / t_size;
  }
  lu_ = std::make_unique<SparseLu>(matrix().pattern());
  step_ = std::make_unique<BorderedStep>(matrix(), b_, c_);
}

const SparseLu* FoldSystem::solve_bordered(std::span<const double> x, std::span<double> f,
                                           std::span<double> base_jac, std::vector<double>& vg,
                                           bool for_step) const {
  const auto n = std::size_t(base().size());
  base().set_parameter(lambda_of(x));
  base().evaluate(x.first(n), f, base_jac);
  const SparseLu* lu = lu_.get();
  if (for_step) {
    if (!step_->factor(base_jac)) return nullptr;
    lu = &step_->factors();
  } else {
    std::vector<double> values(std::size_t(matrix().pattern().nnz()));
    matrix().assemble(base_jac, b_, c_, 0.0, values);
    // The bordered matrix is regular at and near the fold, and consecutive evaluations
    // differ little: the pivot sequence is reused while KLU's growth check allows.
    if (!lu_->refactor(values)) return nullptr;
  }
  vg.assign(n + 1, 0.0);
  vg[n] = 1.0;
  lu->solve(vg);
  return lu;
}

void FoldSystem::second_derivatives(std::span<const double> u, std::span<const double> v,
                                    std::span<const double> w, std::span<double> gradient,
                                    double& parameter_part, const AtState* at_u) const {
  const auto n = u.size();
  const SparsePattern& p = base().pattern();
  // Central: ε³ balances truncation (ε²) against rounding (1e-16/ε). One-sided, from
  // the values at u: ε² balances truncation (ε) against rounding. v has unit size in the
  // metric, so the state moves by about ε relative to its own size.
  const double machine = std::numeric_limits<double>::epsilon();
  const double eps = (at_u ? std::sqrt(machine) : std::cbrt(machine)) * (1.0 + metric().state_norm(u)) /
                     std::max(metric().state_norm(v), std::numeric_limits<double>::min());
  std::vector<double> shifted(n), f(n), jac(std::size_t(p.nnz())), f_lambda(n);
  std::fill(gradient.begin(), gradient.end(), 0.0);
  parameter_part = 0.0;
  // wᵀ J and wᵀ F_λ, weighted, added to the gradient and parameter part.
  auto add = [&](std::span<const double> jacobian, std::span<const double> column, double weight) {
    for (std::size_t row = 0; row < n; ++row) {
      for (Index at = p.row_start[row]; at < p.row_start[row + 1]; ++at)
        gradient[std::size_t(p.column[std::size_t(at)])] += weight * w[row] * jacobian[std::size_t(at)];
      parameter_part += weight * w[row] * column[row];
    }
  };
  for (const double side : {1.0, -1.0}) {
    if (at_u && side < 0.0) break;
    for (std::size_t k = 0; k < n; ++k) shifted[k] = u[k] + side * eps * v[k];
    base().evaluate(shifted, f, jac);
    base().parameter_derivative_given(shifted, f, f_lambda);
    add(jac, f_lambda, at_u ? 1.0 / eps : side / (2.0 * eps));
  }
  if (at_u) add(at_u->jacobian, at_u->parameter_derivative, -1.0 / eps);
}

void FoldSystem::evaluate(std::span<const double> x, std::span<double> residual, std::span<double> jacobian) const {
  const auto n = std::size_t(base().size());
  std::vector<double> base_jac(std::size_t(base().pattern().nnz())), vg;
  // With the Jacobian, M is factored for the Newton step at this J too.
  const SparseLu* lu = solve_bordered(x, residual.first(n), base_jac, vg, !jacobian.empty());
  if (!lu) {
    std::fill(residual.begin(), residual.end(), std::numeric_limits<double>::quiet_NaN());
    return;
  }
  residual[n] = vg[n] - parameter();
  if (jacobian.empty()) return;

  std::vector<double> w(n + 1, 0.0);
  w[n] = 1.0;
  lu->solve_transposed(w);
  const std::span<const double> u = x.first(n);
  std::vector<double> gradient(n), column(n);
  base().parameter_derivative_given(u, residual.first(n), column);
  // Newton's Jacobian needs ∇g only to a few digits more than its steps: the one-sided
  // difference from the values at u saves an assembly.
  const AtState at_u{base_jac, column};
  double parameter_part = 0.0;
  second_derivatives(u, std::span<const double>(vg).first(n), std::span<const double>(w).first(n), gradient,
                     parameter_part, &at_u);
  for (double& g : gradient) g = -g;
  const double scale = metric().parameter_scale();
  for (double& c : column) c *= scale;
  matrix().assemble(base_jac, column, gradient, -parameter_part * scale, jacobian);
}

double FoldSystem::fold_curvature(std::span<const double> x) const { return null_vector_and_curvature(x).second; }

std::pair<std::vector<double>, double> FoldSystem::null_vector_and_curvature(std::span<const double> x) const {
  const auto n = std::size_t(base().size());
  std::vector<double> f(n), base_jac(std::size_t(base().pattern().nnz())), vg;
  const SparseLu* lu = solve_bordered(x, f, base_jac, vg);
  if (!lu) return {{}, std::numeric_limits<double>::quiet_NaN()};
  std::vector<double> w(n + 1, 0.0);
  w[n] = 1.0;
  lu->solve_transposed(w);
  const std::span<const double> u = x.first(n), v = std::span<const double>(vg).first(n);
  std::vector<double> gradient(n), f_lambda(n);
  double parameter_part = 0.0;
  second_derivatives(u, v, std::span<const double>(w).first(n), gradient, parameter_part);
  base().parameter_derivative_given(u, f, f_lambda);
  double bend = 0.0, push = 0.0;  // ψᵀF_uu[v, v], ψᵀF_λ
  for (std::size_t k = 0; k < n; ++k) {
    bend += gradient[k] * v[k];
    push += w[k] * f_lambda[k];
  }
  return {unit_null_vector(std::move(vg)), bend / push};
}

std::vector<double> FoldSystem::left_null_vector(std::span<const double> x) const {
  const auto n = std::size_t(base().size());
  std::vector<double> f(n), base_jac(std::size_t(base().pattern().nnz())), vg;
  const SparseLu* lu = solve_bordered(x, f, base_jac, vg);
  if (!lu) return {};
  std::vector<double> w(n + 1, 0.0);
  w[n] = 1.0;
  lu->solve_transposed(w);
  w.resize(n);
  return w;
}

std::vector<double> FoldSystem::unit_null_vector(std::vector<double> vg) const {
  vg.resize(std::size_t(base().size()));
  const double size = metric().state_norm(vg);
  for (double& c : vg) c /= size;
  return vg;
}

std::vector<double> FoldSystem::null_vector(std::span<const double> x) const {
  const auto n = std::size_t(base().size());
  std::vector<double> f(n), base_jac(std::size_t(base().pattern().nnz())), vg;
  if (!solve_bordered(x, f, base_jac, vg)) return {};
  return unit_null_vector(std::move(vg));
}

}  // namespace twb
