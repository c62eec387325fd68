// Pseudo-arclength continuation round the folds of the model problems, with the folds
// located by the minimally augmented system or, as a fallback, by bracketing t_λ = 0
// (docs/physics.md section 8: distress is such a fold of the bearing's steady branch in load).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>

#include "../support/branch_start.h"
#include "../support/model_problems.h"
#include "solver/arclength_continuation.h"
#include "solver/fold_location.h"

namespace twb {
namespace {

constexpr double tolerance = 1e-10;  // the corrector's residual tolerance (max-norm)

ArclengthSettings settings_for_tests() {
  ArclengthSettings s;
  s.newton.residual_tolerance = tolerance;
  s.newton.max_step = 0.0;  // KINSOL's own default cap: no rigid body to protect here
  return s;
}

void print(const ArclengthReport& r) {
  std::cout << r.message << ": " << r.accepted << " states, " << r.rejected << " rejected, "
            << r.corrector_iterations << " corrector iterations\n  last rejection: " << r.last_rejection << "\n";
  for (const FoldPoint& f : r.folds)
    std::cout << "  fold at λ = " << f.lambda << " by " << to_string(f.method) << " (" << f.iterations
              << " iterations, residual " << f.residual_norm << ")" << (f.message.empty() ? "" : ": " + f.message)
              << "\n";
}

// Semenov, θ' = ψ·e^θ − θ as a DAE (model_problems.h), continued in ψ from 0.1 on the
// lower branch, round the fold at (ψ, θ) = (1/e, 1) and back down the upper branch.
struct SemenovBranch {
  ArclengthReport report;
  std::vector<std::array<double, 3>> points;  // (θ, a, ψ)
};

SemenovBranch continue_semenov(const ArclengthSettings& s) {
  testing::SemenovProblem semenov(0.1);
  SemenovBranch b;
  b.report = continue_by_arclength(semenov, testing::SemenovProblem::lower_steady_state(0.1), semenov.parameter(), s,
                                   [&](const BranchPoint& p) {
                                     b.points.push_back({p.u[0], p.u[1], p.lambda});
                                     return true;
                                   });
  print(b.report);
  return b;
}

// How far the located fold may be from the exact one when Newton stops at
// max|F| ≤ tol, |g| ≤ tol. To first order, a residual r = (r₁, r₂) moves the fold of
// θ − ψa = r₁, a − e^θ = r₂ to θ* = 1 + r₁ + r₂/e, ψ* = 1/e − r₁/e − r₂/e², i.e. by at most
// 1.37·tol in θ and 0.50·tol in ψ. A residual of g slides the point along the branch,
// where g = (1 − θ)/(c₁ + c₂e) with the border c = ω∘t̂ = (0.244, 0.663): θ moves by
// 2.05·|g|, ψ only to second order. Hence |ψ* − 1/e| ≤ 0.51·tol and |θ* − 1| ≤ 3.5·tol.
constexpr double semenov_psi_bound = 0.51 * tolerance, semenov_theta_bound = 3.5 * tolerance;

TEST(FoldContinuation, SemenovFoldByMinimallyAugmentedNewton) {
  ArclengthSettings s = settings_for_tests();
  s.lambda_min = 0.1;  // back down the upper branch to where it started
  const SemenovBranch b = continue_semenov(s);
  ASSERT_EQ(b.report.stop, ArclengthReport::Stop::parameter_bound) << b.report.message;
  ASSERT_EQ(b.report.folds.size(), 1u);
  const FoldPoint& f = b.report.folds[0];
  std::cout << "psi* - 1/e = " << f.lambda - std::exp(-1.0) << ", theta* - 1 = " << f.u[0] - 1.0 << "\n";
  EXPECT_EQ(f.method, FoldMethod::minimally_augmented) << f.message;
  EXPECT_NEAR(f.lambda, std::exp(-1.0), semenov_psi_bound);
  EXPECT_NEAR(f.u[0], 1.0, semenov_theta_bound);
  EXPECT_NEAR(f.u[1], std::exp(1.0), semenov_theta_bound * std::exp(1.0) + tolerance);
  // The null vector of J = [1 −1/e; −e 1] is (1, e), unit in the metric (weights ½, ½).
  // v depends smoothly on the state, so it carries the state's error times an O(1) factor.
  const double length = std::sqrt(0.5 * (1.0 + std::exp(2.0)));
  ASSERT_EQ(f.null_vector.size(), 2u);
  EXPECT_NEAR(std::abs(f.null_vector[0]), 1.0 / length, 100 * tolerance);
  EXPECT_NEAR(std::abs(f.null_vector[1]), std::exp(1.0) / length, 100 * tolerance);
  EXPECT_GT(f.null_vector[0] * f.null_vector[1], 0.0);

  // Every state lies on θ·e^(−θ) = ψ: with |θ − ψa| ≤ tol and |a − e^θ| ≤ tol,
  // |θe^(−θ) − ψ| ≤ (1 + ψ)·tol·e^(−θ) ≤ 2·tol. Before the fold θ < 1, after it θ > 1
  // (the upper branch), and the continuation went back below ψ = 0.1.
  bool passed = false;
  for (const auto& [theta, a, psi] : b.points) {
    EXPECT_NEAR(theta * std::exp(-theta), psi, 2 * tolerance);
    EXPECT_NEAR(a, std::exp(theta), tolerance);
    if (!passed && psi < f.lambda - 1e-3 && theta > 1.0) passed = true;
    if (passed) EXPECT_GT(theta, 1.0);
    else EXPECT_LT(theta, 1.0 + semenov_theta_bound + 0.5);  // at most one step past the fold
  }
  EXPECT_TRUE(passed);
  EXPECT_LT(b.points.back()[2], 0.1);
  EXPECT_GT(b.points.back()[0], 3.0);  // the upper branch at ψ = 0.1 has θ = 3.577
}

// The fallback alone: t_λ = 0 bracketed along the arclength by TOMS 748 to a bracket
// √tol·Δs wide (fold_location.cpp). Δs ≤ max_step, and the metric length of the branch
// per unit θ at the fold is √((1 + e²)/2) = 2.05, so θ* is within √tol·max_step/(2·2.05)
// plus the residual's 1.4·tol. ψ is flat there: ψ(s) ≈ ψ* − ½·0.1·κ_μ(s − s*)² with
// κ_μ = (10/e)/2.05² = 0.88, which adds only ~0.003·tol to the residual's 0.50·tol.
TEST(FoldContinuation, SemenovFoldByArclengthBracket) {
  ArclengthSettings s = settings_for_tests();
  s.fold.minimally_augmented = false;
  s.max_points = 16;  // the fold is passed at the 12th state
  const SemenovBranch b = continue_semenov(s);
  ASSERT_EQ(b.report.folds.size(), 1u);
  const FoldPoint& f = b.report.folds[0];
  std::cout << "psi* - 1/e = " << f.lambda - std::exp(-1.0) << ", theta* - 1 = " << f.u[0] - 1.0 << "\n";
  EXPECT_EQ(f.method, FoldMethod::arclength_bracket) << f.message;
  EXPECT_NEAR(f.lambda, std::exp(-1.0), semenov_psi_bound);
  EXPECT_NEAR(f.u[0], 1.0, std::sqrt(tolerance) * s.max_step / 4.0 + 2 * tolerance);
  EXPECT_LE(f.iterations, s.fold.max_bracket_evaluations);
}

// The exact fold of u'' + λe^u = 0, u(0) = u(1) = 0: u = 2 ln(cosh y / cosh(y(2x − 1))),
// λ = 8y²/cosh²y, whose largest λ has y·tanh y = 1; there u(½) = 2 ln cosh y.
struct BratuFold {
  double lambda, u_max;
};
BratuFold exact_bratu_fold() {
  double y = 1.2;
  for (int k = 0; k < 50; ++k) y -= (y * std::tanh(y) - 1.0) / (std::tanh(y) + y / std::pow(std::cosh(y), 2));
  return {8.0 * y * y / std::pow(std::cosh(y), 2), 2.0 * std::log(std::cosh(y))};
}

struct DiscreteFold {
  FoldPoint fold;
  double u_max = 0;
};

// n odd puts a node at x = ½, where u is largest.
DiscreteFold bratu_fold(int n) {
  testing::BratuProblem bratu(n, 1.0);
  ArclengthSettings s = settings_for_tests();
  const std::vector<double> u0 = testing::steady_state(bratu, std::vector<double>(std::size_t(n), 0.0), s.newton);
  // Stop once on the upper branch, below λ = 3.
  const ArclengthReport r =
      continue_by_arclength(bratu, u0, bratu.parameter(), s, [](const BranchPoint& p) { return !(p.tangent.back() < 0 && p.lambda < 3.0); });
  print(r);
  EXPECT_EQ(r.stop, ArclengthReport::Stop::caller) << r.message;
  EXPECT_EQ(r.folds.size(), 1u);
  if (r.folds.empty()) return {};
  EXPECT_EQ(r.folds[0].method, FoldMethod::minimally_augmented) << r.folds[0].message;
  return {r.folds[0], r.folds[0].u[std::size_t(n / 2)]};
}

// The discrete fold differs from the continuum one by O(h²) (second-order differences),
// which at h = 1/100 is ~1e-5 relative, far above what the fold's Newton leaves (~tol).
// Halving h must cut both errors four-fold: observed orders within 2 ± 0.1. The issue's
// demand, 0.5 % of λ*, then holds with a wide margin.
TEST(FoldContinuation, BratuFoldConvergesAtSecondOrder) {
  const BratuFold exact = exact_bratu_fold();
  EXPECT_NEAR(exact.lambda, testing::BratuProblem::critical_parameter(), 1e-9);
  const DiscreteFold coarse = bratu_fold(99), fine = bratu_fold(199);
  ASSERT_FALSE(coarse.fold.u.empty());
  ASSERT_FALSE(fine.fold.u.empty());
  const double e_lambda[2] = {coarse.fold.lambda - exact.lambda, fine.fold.lambda - exact.lambda};
  const double e_u[2] = {coarse.u_max - exact.u_max, fine.u_max - exact.u_max};
  std::cout << "λ* error " << e_lambda[0] << ", " << e_lambda[1] << "; u_max error " << e_u[0] << ", " << e_u[1]
            << " (exact λ* " << exact.lambda << ", u_max " << exact.u_max << ")\n";
  EXPECT_NEAR(std::log2(e_lambda[0] / e_lambda[1]), 2.0, 0.1);
  EXPECT_NEAR(std::log2(e_u[0] / e_u[1]), 2.0, 0.1);
  EXPECT_LT(std::abs(e_lambda[1]), 5e-3 * exact.lambda);
  EXPECT_LT(std::abs(e_u[1]), 5e-3 * exact.u_max);
  // The null vector is the principal eigenfunction of the linearization: one sign.
  for (double v : fine.fold.null_vector) EXPECT_GT(v * fine.fold.null_vector[99], 0.0);
}

// A caller that needs the fold's load alone (an error bar's refined fold): Newton from a
// guess 30 % off in u and 10 % in λ stops once λ is settled to the accuracy asked, with
// λ then within it of the fully converged fold (Newton's error past its first steps is
// below its last step: NewtonSettings::watched), and in fewer iterations.
TEST(FoldContinuation, FoldLoadAloneStopsOnceTheLoadIsSettled) {
  const DiscreteFold exact = bratu_fold(99);
  ASSERT_FALSE(exact.fold.u.empty());
  testing::BratuProblem bratu(99, 1.0);
  std::vector<double> guess = exact.fold.u;
  for (double& v : guess) v *= 0.7;
  NewtonSettings newton = settings_for_tests().newton;
  // One Jacobian for several iterations: Newton's convergence becomes linear, as it is
  // across the bearing's kinks, where settling λ early saves iterations (quadratic
  // convergence settles λ and the residual together).
  newton.jacobian_reuse = 4;
  const double guess_lambda = 0.9 * exact.fold.lambda;
  const FoldPoint full = locate_fold_near(bratu, guess, guess_lambda, exact.fold.null_vector, newton);
  const double accuracy = 1e-4 * exact.fold.lambda;
  const FoldPoint quick = locate_fold_near(bratu, guess, guess_lambda, exact.fold.null_vector, newton, accuracy);
  ASSERT_FALSE(full.u.empty()) << full.message;
  ASSERT_FALSE(quick.u.empty()) << quick.message;
  std::cout << "full: " << full.iterations << " iterations, lambda " << full.lambda << "; load alone: "
            << quick.iterations << " iterations, lambda " << quick.lambda << "\n";
  EXPECT_NEAR(full.lambda, exact.fold.lambda, 1e-8 * exact.fold.lambda);  // the same fold
  EXPECT_NEAR(quick.lambda, full.lambda, accuracy);
  EXPECT_LT(quick.iterations, full.iterations);
  EXPECT_GT(quick.curvature, 0.0);  // still told the kind of fold: λ's largest
}

}  // namespace
}  // namespace twb
