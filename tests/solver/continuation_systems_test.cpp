// The pieces continuation is built from: the bordered pattern and its KLU solves against
// a dense solve, the exact Jacobians of the arclength and fold systems against central
// differences, and the tangent's orientation.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "../support/branch_start.h"
#include "../support/derivative_check.h"
#include "../support/model_problems.h"
#include "solver/arclength_system.h"
#include "solver/bordered_matrix.h"
#include "solver/fold_system.h"
#include "solver/sparse_lu.h"

namespace twb {
namespace {

Eigen::MatrixXd dense(const SparsePattern& p, const std::vector<double>& values) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(p.rows, p.cols);
  for (Index r = 0; r < p.rows; ++r)
    for (Index at = p.row_start[std::size_t(r)]; at < p.row_start[std::size_t(r + 1)]; ++at)
      m(r, p.column[std::size_t(at)]) = values[std::size_t(at)];
  return m;
}

// A bordered tridiagonal matrix: KLU's solves with it and its transpose match Eigen's
// dense LU to rounding (the matrix is well conditioned: diagonally dominant A, O(1) border).
TEST(ContinuationSystems, BorderedSolvesMatchDenseLu) {
  testing::BratuProblem bratu(7, 1.0);
  const SparsePattern& base = bratu.pattern();
  std::vector<double> a(std::size_t(base.nnz()));
  for (std::size_t k = 0; k < a.size(); ++k) a[k] = 0.3 + 0.1 * double(k % 5);
  for (Index i = 0; i < base.rows; ++i) a[std::size_t(base.find(i, i))] = 4.0 + double(i);
  const std::vector<double> column = {1, -2, 0.5, 0, 3, 1, -1}, row = {0.2, 0, 1, -1, 0.5, 2, 1};
  const BorderedMatrix m(base);
  std::vector<double> values(std::size_t(m.pattern().nnz()));
  m.assemble(a, column, row, -0.7, values);
  const Eigen::MatrixXd full = dense(m.pattern(), values);
  EXPECT_DOUBLE_EQ(full(3, 7), column[3]);
  EXPECT_DOUBLE_EQ(full(7, 6), row[6]);
  EXPECT_DOUBLE_EQ(full(7, 7), -0.7);
  EXPECT_DOUBLE_EQ(full(2, 2), a[std::size_t(base.find(2, 2))]);

  SparseLu lu(m.pattern());
  ASSERT_TRUE(lu.factor(values));
  Eigen::VectorXd rhs(8);
  rhs << 1, 2, 3, 4, 5, 6, 7, 8;
  std::vector<double> x(rhs.data(), rhs.data() + 8), y = x;
  lu.solve(x);
  lu.solve_transposed(y);
  const Eigen::VectorXd ex = full.lu().solve(rhs), ey = full.transpose().lu().solve(rhs);
  for (int k = 0; k < 8; ++k) {
    EXPECT_NEAR(x[std::size_t(k)], ex(k), 1e-13 * ex.cwiseAbs().maxCoeff());
    EXPECT_NEAR(y[std::size_t(k)], ey(k), 1e-13 * ey.cwiseAbs().maxCoeff());
  }
}

// Bratu on 12 nodes at λ = 3.3, on the lower branch, near its fold (λ* ≈ 3.5).
struct BratuNearFold : ::testing::Test {
  testing::BratuProblem bratu{12, 3.3};
  std::vector<double> u = testing::steady_state(bratu, std::vector<double>(12, 0.5), NewtonSettings{});
  ContinuationMetric metric = ContinuationMetric::of(bratu);
};

TEST_F(BratuNearFold, ArclengthJacobianIsExact) {
  ArclengthSystem arc(bratu, metric);
  std::vector<double> x = arc.extend(u, 3.3), t(13, 0.1);
  t[12] = 0.3;
  arc.set_step(x, t, 0.2);
  x[4] += 0.05;  // off the hyperplane and off the branch
  x[12] += 0.01;
  testing::expect_derivatives_match(arc, x);
}

// The fold system's ∇g and ∂g/∂λ are central differences of the exact Jacobian along the
// null vector (error ~ε² ≈ 4e-11 of the third derivatives); the check's own differences of
// g go through a KLU solve of a matrix with condition ~1e3, still far below 1e-6.
TEST_F(BratuNearFold, FoldSystemJacobianMatchesDifferences) {
  ArclengthSystem arc(bratu, metric);
  const std::vector<double> x = arc.extend(u, 3.3);
  std::vector<double> along_lambda(13, 0.0);
  along_lambda[12] = 1.0;
  const std::vector<double> t = arc.tangent(x, along_lambda);
  std::vector<double> f_lambda(12);
  bratu.parameter_derivative(u, f_lambda);
  FoldSystem fold(bratu, metric, f_lambda, t);
  testing::expect_derivatives_match(fold, x);
}

// The tangent solves J·t_u + λ_scale·F_λ·t_μ = 0, has unit length in the metric and keeps
// the reference's orientation: on Bratu's lower branch u grows with λ.
TEST_F(BratuNearFold, TangentIsUnitAndOriented) {
  ArclengthSystem arc(bratu, metric);
  const std::vector<double> x = arc.extend(u, 3.3);
  for (const double sign : {1.0, -1.0}) {
    std::vector<double> reference(13, 0.0);
    reference[12] = sign;
    const std::vector<double> t = arc.tangent(x, reference);
    EXPECT_NEAR(metric.norm(t), 1.0, 1e-14);
    EXPECT_GT(sign * t[12], 0.0);
    EXPECT_GT(sign * t[6], 0.0);
    std::vector<double> r(12), jac(std::size_t(bratu.pattern().nnz())), fl(12);
    bratu.evaluate(u, r, jac);
    bratu.parameter_derivative(u, fl);
    const SparsePattern& p = bratu.pattern();
    for (Index i = 0; i < 12; ++i) {
      double row = fl[std::size_t(i)] * metric.parameter_scale() * t[12];
      for (Index at = p.row_start[std::size_t(i)]; at < p.row_start[std::size_t(i + 1)]; ++at)
        row += jac[std::size_t(at)] * t[std::size_t(p.column[std::size_t(at)])];
      EXPECT_NEAR(row, 0.0, 1e-10);
    }
  }
}

}  // namespace
}  // namespace twb
