// KinsolNewton::factorization() is shared (natural continuation's tangents, the
// pseudo-time stepper): a tangent factored into it equals one from a factorization of
// its own, and a foreign factorization between Newton solves leaves Newton's iterates
// as they were (KINSOL sets its Jacobian up again at every iteration).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/model_problems.h"
#include "solver/kinsol_newton.h"
#include "solver/sparse_lu.h"

namespace twb {
namespace {

// u_λ from J·u_λ = −F_λ, factored into lu.
std::vector<double> tangent(const SteadySystem& system, SparseLu& lu, const std::vector<double>& u) {
  std::vector<double> r(u.size()), jac(std::size_t(system.pattern().nnz())), s(u.size());
  system.evaluate(u, r, jac);
  EXPECT_TRUE(lu.factor(jac));
  system.parameter_derivative(u, s);
  for (double& c : s) c = -c;
  lu.solve(s);
  return s;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

TEST(SharedFactorization, GivesTheTangentAndLeavesNewtonAsItWas) {
  // Bratu at λ = 3, near its fold at 3.51: J is nearly singular, u_λ about 0.5.
  testing::BratuProblem bratu(100, 3.0);
  const NewtonSettings settings{.residual_tolerance = 1e-10, .max_step = 0.0};
  const std::vector<double> zero(100, 0.0);

  KinsolNewton fresh(bratu);
  std::vector<double> expected = zero;
  const NewtonReport expected_rep = fresh.solve(expected, settings);
  ASSERT_TRUE(expected_rep.converged) << expected_rep.message;

  KinsolNewton shared(bratu);
  std::vector<double> u = zero;
  ASSERT_TRUE(shared.solve(u, settings).converged);
  SparseLu own(bratu.pattern());
  const std::vector<double> t_own = tangent(bratu, own, u);
  const std::vector<double> t_shared = tangent(bratu, shared.factorization(), u);
  double size = 0.0;
  for (double c : t_own) size = std::max(size, std::abs(c));
  ASSERT_GT(size, 0.1);
  // The same matrix, analysis and pivoting: the same solve, to rounding.
  EXPECT_LE(largest_difference(t_shared, t_own), 1e-13 * size);

  // Newton again from the start, after the tangent's factorization: the same iterates.
  std::vector<double> again = zero;
  const NewtonReport rep = shared.solve(again, settings);
  ASSERT_TRUE(rep.converged) << rep.message;
  EXPECT_EQ(rep.iterations, expected_rep.iterations);
  EXPECT_LE(largest_difference(again, expected), 1e-12);
}

}  // namespace
}  // namespace twb
