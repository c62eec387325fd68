// The fold system's Newton step from its bordered matrix's factors (bordered_step.h)
// against a direct KLU solve of the Jacobian as assembled: the same step to rounding,
// whatever was factored between the setup and the solve, and with a border far larger
// than M's.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <limits>

#include "../support/branch_start.h"
#include "../support/model_problems.h"
#include "solver/arclength_system.h"
#include "solver/fold_system.h"
#include "solver/kinsol_newton.h"
#include "solver/sparse_lu.h"
#include "twb/error_family.h"

namespace twb {
namespace {

Eigen::MatrixXd dense(const SparsePattern& p, std::span<const double> values) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(p.rows, p.cols);
  for (Index r = 0; r < p.rows; ++r)
    for (Index at = p.row_start[std::size_t(r)]; at < p.row_start[std::size_t(r + 1)]; ++at)
      m(r, p.column[std::size_t(at)]) = values[std::size_t(at)];
  return m;
}

// Bratu on 12 nodes at λ = 3.3, near its fold (λ* ≈ 3.5): the fold system there.
struct FoldStep : ::testing::Test {
  testing::BratuProblem bratu{12, 3.3};
  std::vector<double> u = testing::steady_state(bratu, std::vector<double>(12, 0.5), NewtonSettings{});
  ContinuationMetric metric = ContinuationMetric::of(bratu);
  std::vector<double> x, t;
  std::unique_ptr<FoldSystem> fold;
  void SetUp() override {
    ArclengthSystem arc(bratu, metric);
    x = arc.extend(u, 3.3);
    std::vector<double> along_lambda(13, 0.0);
    along_lambda[12] = 1.0;
    t = arc.tangent(x, along_lambda);
    std::vector<double> f_lambda(12);
    bratu.parameter_derivative(u, f_lambda);
    fold = std::make_unique<FoldSystem>(bratu, metric, f_lambda, t);
  }
  std::vector<double> jacobian_at(const std::vector<double>& at) {
    std::vector<double> r(13), jac(std::size_t(fold->pattern().nnz()));
    fold->evaluate(at, r, jac);
    return jac;
  }
  // A⁻¹·rhs by KLU on A as assembled, and the bound on its difference from another
  // backward-stable solve: both within κ(A)·ε·|x| of the exact step (a factor 100 for
  // the dimension and the growth of either factorization).
  std::vector<double> direct(const std::vector<double>& jac, const std::vector<double>& rhs, double& allowance) {
    SparseLu lu(fold->pattern());
    EXPECT_TRUE(lu.factor(jac));
    std::vector<double> step = rhs;
    lu.solve(step);
    const Eigen::MatrixXd a = dense(fold->pattern(), jac);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a);
    const double condition = svd.singularValues()(0) / svd.singularValues()(12);
    double size = 0.0;
    for (double v : step) size = std::max(size, std::abs(v));
    allowance = 100.0 * condition * std::numeric_limits<double>::epsilon() * size;
    return step;
  }
  const std::vector<double> rhs = {1, -2, 3, 0.5, -1, 2, 0, 1, -3, 2, 1, -1, 0.7};
  // The step solver set up with `jac` (then `between` called) solves as KLU does on it.
  void expect_step_of(const std::vector<double>& jac, const std::function<void()>& between = {}) {
    NewtonStepSolver* step = fold->step_solver();
    ASSERT_NE(step, nullptr);
    double allowance = 0.0;
    const std::vector<double> expected = direct(jac, rhs, allowance);
    ASSERT_TRUE(step->setup(jac));
    if (between) between();
    std::vector<double> got = rhs;
    ASSERT_TRUE(step->solve(got));
    for (std::size_t k = 0; k < got.size(); ++k) EXPECT_NEAR(got[k], expected[k], allowance) << k;
  }
};

TEST_F(FoldStep, IsTheDirectSolveOfTheAssembledJacobian) { expect_step_of(jacobian_at(x)); }

// KINSOL may evaluate a new point with its Jacobian between a setup and a solve (or set
// up with a Jacobian that is not the last evaluated): the step is still the setup's.
TEST_F(FoldStep, IsTheSetupsWhateverWasFactoredSince) {
  std::vector<double> other = x;
  other[5] += 0.05;
  other[12] += 0.01;
  const std::vector<double> jac = jacobian_at(x);
  jacobian_at(other);  // M factored at another J before the setup
  expect_step_of(jac, [&] { jacobian_at(other); });  // and again between the setup and the solve
}

// A's last column and row scaled far from M's borders (a load in newtons against a unit
// border): the rank-two change is scaled first, so no digits are lost to cancellation.
TEST_F(FoldStep, KeepsItsDigitsWithLargeBorders) {
  std::vector<double> jac = jacobian_at(x);
  const SparsePattern& p = fold->pattern();
  for (Index i = 0; i < 12; ++i) jac[std::size_t(p.row_start[std::size_t(i + 1)] - 1)] *= 1e8;
  for (Index j = 0; j <= 12; ++j) jac[std::size_t(p.row_start[12] + j)] *= 1e-6;
  expect_step_of(jac);
}

// Newton on the fold system, with its own steps, converges to Bratu's fold; KINSOL has
// then no factorization of its own to lend.
TEST_F(FoldStep, NewtonReachesTheFold) {
  KinsolNewton newton(*fold);
  std::vector<double> root = x;
  const NewtonReport rep = newton.solve(root, NewtonSettings{});
  ASSERT_TRUE(rep.converged) << rep.message;
  std::vector<double> r(13);
  fold->evaluate(root, r, {});
  for (double v : r) EXPECT_LE(std::abs(v), NewtonSettings{}.residual_tolerance);
  // Bratu's fold on this grid: λ* ≈ 3.5 (3.51 in the continuum).
  EXPECT_NEAR(fold->lambda_of(root), 3.5, 0.1);
  EXPECT_THROW(newton.factorization(), InternalError);
}

}  // namespace
}  // namespace twb
