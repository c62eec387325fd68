// The fold continued in a second parameter (fold_curve.h) on model problems whose fold
// curves and cusp are known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/bratu_fold.h"
#include "../support/lower_branch.h"
#include "../support/model_problems.h"
#include "solver/arclength_continuation.h"
#include "solver/fold_curve.h"

namespace twb {
namespace {

struct Activation final : SecondParameter {
  explicit Activation(testing::SemenovProblem& s) : semenov(s) {}
  double value() const override { return semenov.activation(); }
  void set(double e) override { semenov.set_activation(e); }
  testing::SemenovProblem& semenov;
};

struct Length final : SecondParameter {
  explicit Length(testing::BratuProblem& b) : bratu(b) {}
  double value() const override { return bratu.length(); }
  void set(double l) override { bratu.set_length(l); }
  testing::BratuProblem& bratu;
};

// The first fold of the branch from the lower state at λ0, located by arclength.
FoldPoint first_fold(SteadySystem& system, std::vector<double> start, double lambda0) {
  system.set_parameter(lambda0);
  ArclengthSettings arc;
  arc.initial_step = 0.02;
  arc.max_step = 0.1;
  arc.max_points = 400;
  const ArclengthReport rep = continue_by_arclength(system, start, system.parameter(), arc);
  if (rep.folds.empty()) throw std::runtime_error("no fold: " + rep.message);
  return rep.folds.front();
}

// Semenov with activation energy ε: folds where (1 + εθ)² = θ, ψ = θ·e^(−θ/(1+εθ)); the
// two meet at the cusp ε = 1/4, θ = 4, ψ = 4e⁻². From the ignition fold at ε = 0.18 the
// curve runs up in ε to the cusp, turns back, and returns as the extinction fold. Every
// point lies on the closed form to the corrector's tolerance (1e-10 in F and g: ψ to
// ~1e-9), the turn is a cusp located by bracketing t_ε = 0: ε to its quadratic accuracy
// ½κΔs²·tol and ψ, θ better than 1e-6.
TEST(FoldCurve, SemenovCuspInClosedForm) {
  testing::SemenovProblem semenov(0.3, 0.18);
  const FoldPoint fold = first_fold(semenov, testing::lower_branch_state(semenov, 0.3), 0.3);
  ASSERT_NEAR(fold.lambda, semenov.ignition_parameter(), 1e-8);
  Activation activation(semenov);
  FoldCurveSettings s;
  s.p_min = 0.15;  // the extinction fold's θ grows like 1/ε² as ε falls: stop at 0.15 (θ ≈ 30)
  s.p_max = 0.4;
  s.direction = +1;
  // The state runs to θ ≈ 30, a ≈ e^6 past the cusp: steps up to one unit of the state.
  s.arclength.initial_step = 0.02;
  s.arclength.max_step = 1.0;
  s.arclength.max_points = 600;
  const FoldCurve curve = trace_fold_curve(semenov, activation, fold, s);
  ASSERT_GT(curve.points.size(), 10u) << curve.message;
  for (const FoldCurvePoint& p : curve.points) {
    const double theta = p.u[0], eps = p.p;
    EXPECT_NEAR(std::pow(1 + eps * theta, 2), theta, 1e-8 * theta) << "ε = " << eps;
    EXPECT_NEAR(p.lambda, theta * std::exp(-theta / (1 + eps * theta)), 1e-9) << "ε = " << eps;
  }
  ASSERT_EQ(curve.turns.size(), 1u) << curve.message;
  const CurveTurn& cusp = curve.turns.front();
  EXPECT_TRUE(cusp.cusp);
  EXPECT_NEAR(cusp.p, 0.25, 1e-8);
  EXPECT_NEAR(cusp.lambda, 4.0 * std::exp(-2.0), 1e-6);
  EXPECT_NEAR(cusp.point.u[0], 4.0, 1e-3);
  // Ignition (the branch's largest ψ) before the cusp, extinction after it.
  EXPECT_GT(curve.points.front().curvature, 0.0);
  EXPECT_LT(curve.points.back().curvature, 0.0);
  EXPECT_LT(curve.points.back().p, s.p_min) << curve.message;  // back down past the lower bound
}

// Bratu on (0, L) is the unit problem with λ·L²: on the grid too, so the fold curve in L
// is λ*(L) = λ*_grid/L² exactly, to the fold system's tolerance. No turn in L.
TEST(FoldCurve, BratuFoldInTheDomainLength) {
  const int n = 49;
  testing::BratuProblem bratu(n, 0.0);
  const FoldPoint fold = first_fold(bratu, testing::lower_branch_state(bratu, 3.0), 3.0);
  const double grid_fold = testing::bratu_grid_fold(n);
  ASSERT_NEAR(fold.lambda, grid_fold, 1e-8 * grid_fold);
  Length length(bratu);
  FoldCurveSettings s;
  s.p_min = 0.5;
  s.p_max = 2.0;
  s.direction = +1;
  s.arclength.initial_step = 0.05;
  s.arclength.max_step = 0.2;
  const FoldCurve curve = trace_fold_curve(bratu, length, fold, s);
  ASSERT_GT(curve.points.size(), 5u) << curve.message;
  EXPECT_GT(curve.points.back().p, 2.0) << curve.message;
  for (const FoldCurvePoint& p : curve.points) {
    EXPECT_NEAR(p.lambda * p.p * p.p, grid_fold, 1e-8 * grid_fold) << "L = " << p.p;
    EXPECT_GT(p.curvature, 0.0);
  }
  EXPECT_TRUE(curve.turns.empty());
}

}  // namespace
}  // namespace twb
