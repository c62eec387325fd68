// Natural-parameter continuation: what a predictor saves the corrector, and a clear stop
// (not a hang, not a jump) when the branch turns back at a fold (docs/physics.md section 8).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "../support/branch_start.h"
#include "../support/model_problems.h"
#include "solver/arclength_continuation.h"
#include "solver/natural_continuation.h"
#include "solver/sparse_lu.h"

namespace twb {
namespace {

constexpr double tolerance = 1e-10;

NaturalSettings settings_with(Predictor predictor) {
  NaturalSettings s;
  s.newton.residual_tolerance = tolerance;
  s.newton.max_step = 0.0;
  s.predictor = predictor;
  return s;
}

// Bratu on 100 nodes from λ = 0.5 to 3.0 (the fold is at 3.51) in 25 equal steps, the
// same for every predictor (no growth, none rejected), so that only Newton's first
// iterate differs: O(Δλ·u_λ) away from the new state for the last state, O(Δλ²·u_λλ) for
// the secant and the tangent. Newton's error squares every iteration, so at Δλ = 0.1
// and a 1e-10 residual the last state costs 3 iterations a step where u_λ is O(1), the
// extrapolations 2: a ratio of 2/3, nearer 1 only where u_λ is small (low λ) or where
// u_λλ grows (near the fold). At most ¾ is asserted.
NaturalReport bratu_ramp(Predictor predictor) {
  testing::BratuProblem bratu(100, 0.5);
  NaturalSettings s = settings_with(predictor);
  std::vector<double> u = testing::steady_state(bratu, std::vector<double>(100, 0.0), s.newton);
  s.initial_step = s.max_step = 0.1;
  s.growth = 1.0;
  const double start = bratu.parameter();
  const NaturalReport r = continue_in_parameter(bratu, u, start, 3.0, s);
  std::cout << "predictor " << int(predictor) << ": " << r.accepted << " steps, " << r.rejected << " rejected, "
            << r.corrector_iterations << " corrector iterations\n";
  EXPECT_TRUE(r.reached_target) << r.message;
  EXPECT_EQ(r.accepted, 25);
  EXPECT_EQ(r.rejected, 0) << r.last_rejection;
  EXPECT_DOUBLE_EQ(r.lambda, 3.0);
  EXPECT_EQ(bratu.parameter(), start);  // given back as it was
  return r;
}

TEST(NaturalContinuation, PredictorSavesCorrectorIterations) {
  const long constant = bratu_ramp(Predictor::constant).corrector_iterations;
  const long secant = bratu_ramp(Predictor::secant).corrector_iterations;
  const long tangent = bratu_ramp(Predictor::tangent).corrector_iterations;
  EXPECT_LE(4 * secant, 3 * constant);
  EXPECT_LE(4 * tangent, 3 * constant);
}

// One branch in legs (as the distress search walks it, stopping to judge states): each
// leg that starts where the last ended reuses the solver's symbolic analysis and the
// slope there, so five legs cost one analysis instead of five, and land on the same
// state as one continuation over the whole interval (both converge to the residual
// tolerance on a branch with one state per λ: they agree to the tolerance over the
// smallest singular value of J, far from the fold O(1) on Bratu).
TEST(NaturalContinuation, LegsReuseTheAnalysisAndReachTheSameState) {
  testing::BratuProblem bratu(100, 0.5);
  NaturalSettings s = settings_with(Predictor::tangent);
  const std::vector<double> start = testing::steady_state(bratu, std::vector<double>(100, 0.0), s.newton);
  s.initial_step = s.max_step = 0.1;

  std::vector<double> whole = start;
  ASSERT_TRUE(continue_in_parameter(bratu, whole, bratu.parameter(), 3.0, s).reached_target);

  bratu.set_parameter(0.5);
  std::vector<double> legs = start;
  const SparseLu::Counts before = SparseLu::thread_counts();
  NaturalContinuation branch(bratu);
  double from = 0.5;
  for (double target : {1.0, 1.5, 2.0, 2.5, 3.0}) {
    ASSERT_TRUE(branch.continue_to(legs, from, target, s).reached_target);
    from = target;
  }
  EXPECT_EQ(SparseLu::thread_counts().analyses - before.analyses, 1);
  EXPECT_EQ(SparseLu::thread_counts().factorizations - before.factorizations, 1);  // the first slope's
  for (std::size_t k = 0; k < legs.size(); ++k) EXPECT_NEAR(legs[k], whole[k], 1e3 * tolerance);

  // A leg from another state (or λ) than the last one's end computes its slope afresh.
  std::vector<double> elsewhere = start;
  const SparseLu::Counts again = SparseLu::thread_counts();
  ASSERT_TRUE(branch.continue_to(elsewhere, 0.5, 1.0, s).reached_target);
  EXPECT_EQ(SparseLu::thread_counts().analyses - again.analyses, 0);
  EXPECT_GE(SparseLu::thread_counts().factorizations - again.factorizations, 1);
}

// Every accepted state is handed over, converged, at increasing λ; false stops there.
TEST(NaturalContinuation, CallbackSeesEveryStateAndCanStop) {
  testing::SemenovProblem semenov(0.1);
  std::vector<double> u = testing::SemenovProblem::lower_steady_state(0.1);
  int calls = 0;
  double last = 0.0;
  const NaturalReport r = continue_in_parameter(semenov, u, 0.1, 0.3, settings_with(Predictor::secant),
                                                [&](const BranchPoint& p) {
                                                  EXPECT_EQ(p.index, calls);
                                                  EXPECT_GE(p.lambda, last);
                                                  EXPECT_NEAR(p.u[0] * std::exp(-p.u[0]), p.lambda, 2 * tolerance);
                                                  EXPECT_EQ(semenov.parameter(), p.lambda);  // the contract
                                                  last = p.lambda;
                                                  return ++calls < 4;
                                                });
  EXPECT_FALSE(r.reached_target);
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(r.accepted, 3);
  EXPECT_DOUBLE_EQ(r.lambda, last);
  EXPECT_EQ(semenov.parameter(), 0.1);  // given back as it was
  EXPECT_NE(r.message.find("caller"), std::string::npos);
}

// Where the branch nears its fold, u* − u ∝ √d with d = λ* − λ: |du/dλ| → ∞, and the
// tangent's prediction misses by about Δλ/(4d) of the change it predicts. Steps longer
// than d find no state (or miss by more than half) and are halved; shorter ones are
// accepted and shrink d. So the continuation creeps up to within a few minimum steps of
// the fold and stops there, below it, on the lower branch, saying so. Every approach
// halves from at most the initial step down to the minimum one, so the number of
// corrections stays bounded.
void expect_stop_below_fold(const NaturalReport& r, double fold, double interval) {
  const double min_step = 1e-6 * interval;  // NaturalSettings' default
  std::cout << r.message << "\n" << r.accepted << " accepted, " << r.rejected << " rejected, "
            << r.corrector_iterations << " iterations; λ* − λ = " << fold - r.lambda << " = "
            << (fold - r.lambda) / min_step << " minimum steps\n";
  EXPECT_FALSE(r.reached_target);
  EXPECT_GT(r.lambda, fold - 10 * min_step);
  EXPECT_LT(r.lambda, fold);
  EXPECT_NE(r.message.find("fold"), std::string::npos);
  EXPECT_LT(r.accepted + r.rejected, 200);
}

// Asked for ψ = 0.5 > 1/e, where no steady state exists.
TEST(NaturalContinuation, StopsWithAReportBelowSemenovsFold) {
  testing::SemenovProblem semenov(0.1);
  std::vector<double> u = testing::SemenovProblem::lower_steady_state(0.1);
  const NaturalReport r = continue_in_parameter(semenov, u, semenov.parameter(), 0.5, settings_with(Predictor::secant));
  expect_stop_below_fold(r, std::exp(-1.0), 0.4);
  EXPECT_LT(u[0], 1.0);  // still the lower branch
  EXPECT_NEAR(u[0] * std::exp(-u[0]), r.lambda, 2 * tolerance);
  // Near the fold |du/dλ| ∝ d^(−1/2): from d = 0.27 at ψ = 0.1 to d ≤ 10 minimum steps = 4e-6
  // at the stop it grows at least √(0.27/4e-6) ≈ 260-fold.
  EXPECT_GT(r.sensitivity_growth, 100.0);
}

// Bratu (n = 100) pushed to λ = 4: the stop lies just below the discrete fold that
// pseudo-arclength continuation locates on the same mesh.
TEST(NaturalContinuation, StopsJustBelowBratusFoldFoundByArclength) {
  testing::BratuProblem bratu(100, 1.0);
  NaturalSettings s = settings_with(Predictor::tangent);
  const std::vector<double> u0 = testing::steady_state(bratu, std::vector<double>(100, 0.0), s.newton);
  ArclengthSettings arc;
  arc.newton = s.newton;
  const ArclengthReport around =
      continue_by_arclength(bratu, u0, bratu.parameter(), arc, [](const BranchPoint& p) { return p.tangent.back() > 0; });
  ASSERT_EQ(around.folds.size(), 1u);
  const double fold = around.folds[0].lambda;

  bratu.set_parameter(1.0);
  std::vector<double> u = u0;
  const NaturalReport r = continue_in_parameter(bratu, u, 1.0, 4.0, s);
  expect_stop_below_fold(r, fold, 3.0);
  EXPECT_LT(u[50], around.folds[0].u[50]);  // the lower branch: u grows along it up to the fold
}

}  // namespace
}  // namespace twb
