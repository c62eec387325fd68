// The model problems themselves: their Jacobians and parameter derivatives against
// central differences, and Semenov's lower branch against its closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/model_problems.h"
#include "twb/solver/kinsol_newton.h"

namespace twb {
namespace {

// Central differences at ε = 1e-6 on O(1)–O(e^θ) smooth terms: truncation ε²·|F'''|
// ≈ 1e-12·e^θ, rounding 1e-16·|F|/ε ≈ 1e-10·max|F|; 1e-6 relative holds with margin.
void expect_derivatives_match(SteadySystem& s, std::vector<double> u) {
  const auto n = std::size_t(s.size());
  const SparsePattern& p = s.pattern();
  std::vector<double> r(n), jac(std::size_t(p.nnz())), rp(n), rm(n), dl(n);
  s.evaluate(u, r, jac);
  const double eps = 1e-6;
  for (std::size_t c = 0; c < n; ++c) {
    std::vector<double> up = u, um = u;
    up[c] += eps;
    um[c] -= eps;
    s.evaluate(up, rp, {});
    s.evaluate(um, rm, {});
    for (std::size_t row = 0; row < n; ++row) {
      const double fd = (rp[row] - rm[row]) / (2 * eps);
      const Index at = p.find(Index(row), Index(c));
      const double exact = at >= 0 ? jac[std::size_t(at)] : 0.0;
      EXPECT_NEAR(exact, fd, 1e-6 * std::max(1.0, std::abs(fd))) << row << "," << c;
    }
  }
  s.parameter_derivative(u, dl);
  const double l = s.parameter(), el = 1e-6 * std::max(1.0, std::abs(l));
  s.set_parameter(l + el);
  s.evaluate(u, rp, {});
  s.set_parameter(l - el);
  s.evaluate(u, rm, {});
  s.set_parameter(l);
  for (std::size_t row = 0; row < n; ++row)
    EXPECT_NEAR(dl[row], (rp[row] - rm[row]) / (2 * el), 1e-6 * std::max(1.0, std::abs(dl[row])));
}

TEST(ModelProblems, SemenovDerivatives) {
  testing::SemenovProblem s(0.3);
  expect_derivatives_match(s, {0.7, 1.9});
}

TEST(ModelProblems, IgnitionDerivatives) {
  testing::SemenovProblem s(0.45, 0.2);
  expect_derivatives_match(s, {1.7, 3.1});
}

// The ignition fold's closed form against the S-curve ψ(θ) = θ·exp(−θ/(1 + εθ)): it
// must be the curve's local maximum on the lower side (θ < 5 for ε = 0.2), found here
// by golden-section search. The search brackets θ to 1e-9; ψ is flat there, so its
// maximum is found to O(1e-18): 1e-12 is rounding.
TEST(ModelProblems, IgnitionFoldIsTheCurvesMaximum) {
  const double eps = 0.2;
  const testing::SemenovProblem s(0.0, eps);
  const auto psi = [eps](double t) { return t * std::exp(-t / (1.0 + eps * t)); };
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = 0.0, b = 5.0;
  while (b - a > 1e-9) {
    const double c = b - golden * (b - a), d = a + golden * (b - a);
    (psi(c) > psi(d) ? b : a) = psi(c) > psi(d) ? d : c;
  }
  EXPECT_NEAR(psi(0.5 * (a + b)), s.ignition_parameter(), 1e-12);
}

TEST(ModelProblems, BratuDerivatives) {
  testing::BratuProblem b(12, 2.0);
  std::vector<double> u(12);
  for (Index i = 0; i < 12; ++i) u[std::size_t(i)] = 0.8 * std::sin(3.14159 * b.x(i)) + 0.01 * double(i);
  expect_derivatives_match(b, u);
}

// KINSOL on the interface reaches Semenov's lower branch from a nearby guess.
TEST(ModelProblems, SemenovLowerBranchByNewton) {
  testing::SemenovProblem s(0.25);
  std::vector<double> u = {0.2, 1.2};
  KinsolNewton newton(s);
  NewtonSettings settings;
  settings.max_step = 0.0;
  const NewtonReport rep = newton.solve(u, settings);
  ASSERT_TRUE(rep.converged) << rep.message;
  const std::vector<double> exact = testing::SemenovProblem::lower_steady_state(0.25);
  EXPECT_NEAR(u[0], exact[0], 1e-10);  // residual tolerance 1e-10 on an O(1) Jacobian
  EXPECT_NEAR(u[0] * std::exp(-u[0]), 0.25, 1e-10);
}

}  // namespace
}  // namespace twb
