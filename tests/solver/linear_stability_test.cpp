// The stability test by shift-invert Arnoldi (linear_stability.h) on problems whose
// relaxation rates are known in closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <boost/math/tools/roots.hpp>

#include "../support/lower_branch.h"
#include "../support/model_problems.h"
#include "solver/arclength_continuation.h"
#include "solver/linear_stability.h"

namespace twb {
namespace {

StabilityReport stability_at(const SteadySystem& system, std::span<const double> u) {
  SparseLu lu(system.pattern());
  std::vector<double> r(u.size()), jac(std::size_t(system.pattern().nnz()));
  system.evaluate(u, r, jac);
  if (!lu.factor(jac)) throw std::runtime_error("singular Jacobian");
  return linear_stability(system, lu);
}

// Bratu at λ = 0 is the discrete heat equation: μ_k = (4/h²)·sin²(kπh/2) exactly. The
// Krylov space of 24 vectors resolves the slowest modes of this symmetric operator to
// rounding (their Ritz values converge like (μ_k/μ_{25})^24), so 1e-10 is a loose bound.
TEST(LinearStability, HeatEquationRatesInClosedForm) {
  const int n = 99;
  testing::BratuProblem bratu(n, 0.0);
  const std::vector<double> u(std::size_t(n), 0.0);
  const StabilityReport rep = stability_at(bratu, u);
  ASSERT_EQ(rep.verdict, Stability::stable) << rep.reason;
  ASSERT_GE(rep.modes.size(), 3u);
  const double h = 1.0 / (n + 1);
  for (int k = 1; k <= 3; ++k) {
    const double exact = 4.0 / (h * h) * std::pow(std::sin(k * M_PI * h / 2.0), 2);
    EXPECT_NEAR(rep.modes[std::size_t(k - 1)].real(), exact, 1e-10 * exact) << "mode " << k;
    EXPECT_NEAR(rep.modes[std::size_t(k - 1)].imag(), 0.0, 1e-10 * exact);
  }
  EXPECT_LE(rep.solves, 24);
}

// Semenov with finite activation energy (ε = 0.2): at ψ = 0.42 three steady states,
// θ e^(−θ/(1+εθ)) = ψ, with the rate μ = 1 − θ/(1+εθ)² of the one differential unknown
// once the algebraic one is eliminated. Lower and upper branch stable, the middle one
// unstable: the elimination through J's solve must get the sign and the value right.
TEST(LinearStability, SemenovBranchesThroughTheAlgebraicUnknown) {
  const double eps = 0.2, psi = 0.42;
  testing::SemenovProblem semenov(psi, eps);
  const auto g = [&](double t) { return t * std::exp(-t / (1 + eps * t)) - psi; };
  // The folds where (1 + εθ)² = θ split the three roots.
  const double b = 2 * eps - 1, disc = std::sqrt(b * b - 4 * eps * eps);
  const double fold1 = (-b - disc) / (2 * eps * eps), fold2 = (-b + disc) / (2 * eps * eps);
  const struct {
    double lo, hi;
    Stability expected;
  } branches[] = {{0.0, fold1, Stability::stable}, {fold1, fold2, Stability::unstable}, {fold2, 200.0, Stability::stable}};
  for (const auto& br : branches) {
    boost::uintmax_t iterations = 200;
    const auto [a, c] =
        boost::math::tools::toms748_solve(g, br.lo, br.hi, boost::math::tools::eps_tolerance<double>(52), iterations);
    const double theta = 0.5 * (a + c);
    const std::vector<double> u{theta, std::exp(theta / (1 + eps * theta))};
    const StabilityReport rep = stability_at(semenov, u);
    EXPECT_EQ(rep.verdict, br.expected) << "θ = " << theta << ": " << rep.reason;
    ASSERT_EQ(rep.modes.size(), 1u);
    const double exact = 1.0 - theta / std::pow(1 + eps * theta, 2);
    EXPECT_NEAR(rep.modes[0].real(), exact, 1e-12 * std::max(1.0, std::abs(exact))) << "θ = " << theta;
  }
}

// Bratu's branch through its fold: below it (lower branch) stable, past the turning
// point (upper branch, same λ) exactly one mode grows. Continued by arclength from the
// lower branch, every state's verdict must follow the sign of the tangent's λ part.
TEST(LinearStability, BratuLosesStabilityAtTheFold) {
  const int n = 49;
  testing::BratuProblem bratu(n, 0.0);
  const std::vector<double> start = testing::lower_branch_state(bratu, 3.0);
  bratu.set_parameter(3.0);
  ArclengthSettings arc;
  arc.initial_step = 0.05;
  arc.max_step = 0.2;
  arc.lambda_min = 2.5;
  arc.max_points = 60;
  int stable = 0, unstable = 0;
  continue_by_arclength(bratu, start, bratu.parameter(), arc, [&](const BranchPoint& p) {
    if (p.index == 0) return true;
    const StabilityReport rep = stability_at(bratu, p.u);
    // Within 1e-3 of the fold the slowest rate is itself tiny: skip the turning point.
    if (std::abs(p.tangent.back()) < 1e-3) return true;
    const Stability expected = p.tangent.back() > 0 ? Stability::stable : Stability::unstable;
    EXPECT_EQ(rep.verdict, expected) << "λ = " << p.lambda << ", t_λ = " << p.tangent.back() << ": " << rep.reason;
    (rep.verdict == Stability::stable ? stable : unstable) += 1;
    if (rep.verdict == Stability::unstable) {
      EXPECT_GT(rep.growth_rate(), 0.0);
    }
    return true;
  });
  EXPECT_GT(stable, 0);
  EXPECT_GT(unstable, 0);
}

}  // namespace
}  // namespace twb
