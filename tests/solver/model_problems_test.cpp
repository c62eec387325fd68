// The model problems themselves: their Jacobians and parameter derivatives against
// central differences, and Semenov's lower branch against its closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/derivative_check.h"
#include "../support/model_problems.h"
#include "solver/kinsol_newton.h"

namespace twb {
namespace {

TEST(ModelProblems, SemenovDerivatives) {
  testing::SemenovProblem s(0.3);
  testing::expect_derivatives_match(s, {0.7, 1.9});
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
  testing::expect_derivatives_match(b, u);
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
