// The fold of the discrete Bratu problem (model_problems.h) on its own grid, so that a
// located critical λ can be judged against the grid's fold rather than the continuum's
// (they differ by O(h²), 5e-5 relative at 100 nodes). Newton on the extended system
//     F(u; λ) = 0,   ∂F/∂u(u; λ)·v = 0,   Σ v_i = 1
// (a null vector of the Jacobian, normalized: the positive first mode), a regular
// system at a quadratic fold, from the lower branch just below the continuum fold.
#pragma once

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "lower_branch.h"
#include "model_problems.h"

namespace twb::testing {

inline double bratu_grid_fold(int interior_nodes) {
  BratuProblem bratu(interior_nodes, 0.0);
  const int n = interior_nodes;
  const SparsePattern& pattern = bratu.pattern();
  const std::vector<double> start = lower_branch_state(bratu, 0.99 * BratuProblem::critical_parameter());
  Eigen::VectorXd u = Eigen::Map<const Eigen::VectorXd>(start.data(), n), v(n);
  for (int i = 0; i < n; ++i) v[i] = std::sin(M_PI * bratu.x(i));
  v /= v.sum();
  double lambda = 0.99 * BratuProblem::critical_parameter();
  std::vector<double> f(static_cast<std::size_t>(n)), values(static_cast<std::size_t>(pattern.nnz()));
  for (int it = 0; it < 50; ++it) {
    bratu.set_parameter(lambda);
    bratu.evaluate(std::span<const double>(u.data(), std::size_t(n)), f, values);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
    for (Index r = 0; r < n; ++r)
      for (Index k = pattern.row_start[std::size_t(r)]; k < pattern.row_start[std::size_t(r + 1)]; ++k)
        J(r, pattern.column[std::size_t(k)]) = values[std::size_t(k)];
    // ∂F/∂λ = −e^u, and ∂(J·v)/∂u = diag(−λ·e^u·v) since only J's diagonal depends on u.
    const Eigen::VectorXd e = u.array().exp().matrix();
    Eigen::VectorXd residual(2 * n + 1);
    residual << Eigen::Map<Eigen::VectorXd>(f.data(), n), J * v, v.sum() - 1.0;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n + 1, 2 * n + 1);
    A.topLeftCorner(n, n) = J;
    A.block(0, 2 * n, n, 1) = -e;
    A.block(n, 0, n, n) = (-lambda * e.cwiseProduct(v)).asDiagonal();
    A.block(n, n, n, n) = J;
    A.block(n, 2 * n, n, 1) = -e.cwiseProduct(v);
    A.block(2 * n, n, 1, n).setOnes();
    const Eigen::VectorXd step = A.partialPivLu().solve(-residual);
    u += step.head(n);
    v += step.segment(n, n);
    lambda += step[2 * n];
    if (step.lpNorm<Eigen::Infinity>() < 1e-13 * (1.0 + u.lpNorm<Eigen::Infinity>())) return lambda;
  }
  throw std::runtime_error("bratu_grid_fold: Newton did not converge");
}

}  // namespace twb::testing
