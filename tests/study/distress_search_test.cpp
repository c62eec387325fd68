// Distress on the bearing (docs/physics.md section 8), on a coarse mesh so it runs in CI: the
// fold located by continuation is proven by two transients, the load bracketed by them
// agrees with the fold, steps just below it settle and just above it run away.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>

#include "../support/table1_scene.h"
#include "solver/kinsol_newton.h"
#include "solver/runaway.h"
#include "study/searches/distress_search.h"
#include "study/searches/steady_solver.h"
#include "study/study_support.h"

namespace twb {
namespace {

// 5 radial × 24 circumferential nodes: the fold moves with the mesh, but the transient
// and the continuation see the same discrete system, so they must agree on it.
Scene coarse_scene(double speed) {
  Scene s = testing::table1_scene(true, true, true, true, speed, 100.0);
  testing::use_coarse_mesh(s);
  return s;
}

// One search shared by every test here (it takes seconds).
struct SharedSearch {
  BearingModel model{coarse_scene(545.0)};
  DistressSearch found;
  double load_given = 0.0, load_after = 0.0;  // the model's load before and after the search
  SharedSearch() {
    DistressSearchSettings settings;
    settings.load_start = 100.0;
    settings.load_end = 600.0;
    settings.bracket_width = 0.002;
    model.set_load(250.0);  // not a load the search visits last
    load_given = model.load();
    found = search_distress(model, settings, {});
    load_after = model.load();
  }
};
SharedSearch& shared() {
  static SharedSearch s;
  return s;
}

class BearingDistress : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = &shared().model;
    found_ = &shared().found;
  }
  BearingModel* model_ = nullptr;
  DistressSearch* found_ = nullptr;
};

// The search moves the load through the branch, the fold and the hot state it marches
// to; its caller's model comes back at the load it was given (a ParameterScope), not
// wherever the search ended.
TEST_F(BearingDistress, TheModelComesBackAtTheLoadItWasGiven) {
  ASSERT_TRUE(found_->row.distress_load) << found_->row.method;
  EXPECT_EQ(shared().load_after, shared().load_given);
}

// The bound: W_d from transients within 1 % of the fold. At a saddle-node the
// runaway threshold is the fold itself, so the only differences are the bracket's width
// (0.2 %) and the two solvers' tolerances (far smaller).
TEST_F(BearingDistress, TransientBracketAgreesWithFold) {
  const DistressRow& row = found_->row;
  ASSERT_FALSE(found_->failed) << found_->message;
  ASSERT_TRUE(row.distress_load && row.bracket_low && row.bracket_high) << row.method;
  ASSERT_TRUE(row.fold_load) << row.method;
  EXPECT_LE((*row.bracket_high - *row.bracket_low) / *row.bracket_high, 0.002 * (1 + 1e-12));
  EXPECT_NEAR(*row.distress_load, *row.fold_load, 0.01 * *row.fold_load) << row.method;
  // Sharper than the issue asks: the fold lies in the bracket, up to the transient's
  // resolution of a slow ghost (a bracket width).
  EXPECT_GE(*row.fold_load, *row.bracket_low * (1 - 0.002));
  EXPECT_LE(*row.fold_load, *row.bracket_high * (1 + 0.002));
}

// The fold comes first and two transients prove it: the bracket is half a width either
// side of the fold, W_d is the fold, and on the paper's branch (every state decided by
// its linear stability) those two are the only transients of the search.
TEST_F(BearingDistress, TheFoldIsProvenByTwoTransients) {
  const DistressRow& row = found_->row;
  ASSERT_TRUE(row.distress_load && row.fold_load && row.bracket_low && row.bracket_high) << row.method;
  EXPECT_EQ(row.verdict, DistressVerdict::fold_proven) << row.method;
  EXPECT_EQ(*row.distress_load, *row.fold_load);
  EXPECT_DOUBLE_EQ(*row.bracket_low, *row.fold_load * (1 - 0.001));
  EXPECT_DOUBLE_EQ(*row.bracket_high, *row.fold_load * (1 + 0.001));
  EXPECT_EQ(found_->counts.transients, 2);
  EXPECT_GT(found_->counts.ida_steps, 0);
  EXPECT_GE(found_->counts.stability_tests, long(found_->cool_states) - 1);
}

// Where the stability test cannot decide (here made to: two Arnoldi vectors cannot
// resolve the three slowest modes it asks for), every state goes to the transient, as
// before the test existed, and the search reaches the same proven fold.
TEST_F(BearingDistress, InconclusiveStabilityFallsBackToTransients) {
  BearingModel model(coarse_scene(545.0));
  DistressSearchSettings settings;
  settings.load_start = 100.0;
  settings.load_end = 600.0;
  settings.stability.krylov_dimension = 2;
  const DistressSearch found = search_distress(model, settings, {});
  ASSERT_TRUE(found.row.distress_load && found_->row.distress_load) << found.row.method;
  // The fold located again from another state of the branch: the same root of the
  // minimally augmented system to its tolerance (F and g within 1e-10; W* then moves by
  // ~1e-9 relative), far inside 1e-7.
  EXPECT_NEAR(*found.row.fold_load, *found_->row.fold_load, 1e-7 * *found_->row.fold_load);
  EXPECT_EQ(found.row.verdict, DistressVerdict::fold_proven) << found.row.method;
  // One transient per state past the start, besides the proof's two.
  EXPECT_GE(found.counts.transients, long(found.cool_states) - 1 + 2);
  EXPECT_GT(found.counts.transients, found_->counts.transients);
}

// 1 % either side of W_d: from the steady state at the bracket's low load, the step
// below settles on a steady state and the step above runs away.
TEST_F(BearingDistress, StepBelowSettlesStepAboveRunsAway) {
  ASSERT_TRUE(found_->row.distress_load);
  const double wd = *found_->row.distress_load, low = *found_->row.bracket_low;
  const RunawaySettings settings = distress_detector(model_->scene(), 0.002);
  const StepOutcome below = classify_step(*model_, found_->bracket_state, low, 0.99 * wd, settings);
  EXPECT_TRUE(below.settled()) << below.reason;
  const StepOutcome above = classify_step(*model_, found_->bracket_state, low, 1.01 * wd, settings);
  EXPECT_FALSE(above.settled()) << above.reason;
}

// Past W_d the run reports where the runaway went: the hot branch, hotter and carried
// by contact, with its trajectory kept.
TEST_F(BearingDistress, RunawayReachesTheHotBranch) {
  ASSERT_FALSE(found_->runaway.empty()) << found_->message;
  const BearingState& before = found_->runaway.front().state;
  const BearingState& after = found_->runaway.back().state;
  EXPECT_GT(after.washer_mean_temperature, before.washer_mean_temperature + 10.0);
  EXPECT_GT(after.contact_share, 0.5);
  EXPECT_LT(before.contact_share, 0.5);
  for (const TrajectorySample& s : found_->runaway) EXPECT_TRUE(std::isfinite(s.state.f_eff));
}

// The robustness demand on the bearing itself: halving or doubling any numeric
// setting of the runaway detector moves W_d by less than 0.5 %. Each variant brackets
// from 1 % below to 1 % above the default W_d, from the steady state 1 % below; both
// brackets are 0.2 % wide around the same dynamics, so a verdict that depended on a
// threshold would show as a shift of a whole bracket or more.
struct DetectorVariant {
  const char* name;
  void (*apply)(RunawaySettings&, double factor);
};

// gtest prints a parameter by its bytes otherwise.
inline void PrintTo(const DetectorVariant& v, std::ostream* os) { *os << v.name; }

class DetectorRobustness : public ::testing::TestWithParam<std::tuple<DetectorVariant, double>> {};

TEST_P(DetectorRobustness, DistressLoadMovesLessThanHalfAPercent) {
  const auto& [variant, factor] = GetParam();
  SharedSearch& s = shared();
  ASSERT_TRUE(s.found.row.distress_load) << s.found.row.method;
  const double wd = *s.found.row.distress_load;
  RunawaySettings settings = distress_detector(s.model.scene(), 0.002);
  variant.apply(settings, factor);
  std::vector<double> low = s.found.bracket_state;
  s.model.set_load(0.99 * wd);
  KinsolNewton newton(s.model);
  ASSERT_TRUE(newton.solve(low, NewtonSettings{}).converged);
  const Bracket b = bracket_critical(s.model, 0.99 * wd, low, 1.01 * wd, settings);
  ASSERT_TRUE(b.valid) << b.message;
  EXPECT_NEAR(b.critical_estimate(), wd, 0.005 * wd) << variant.name << " x" << factor;

  // The proof's two steps keep their verdicts, so W_d (the fold) does not move at all:
  // from 1 % below to the bracket's low end it settles, from there to its high end it
  // runs away.
  const StepOutcome below = classify_step(s.model, low, 0.99 * wd, *s.found.row.bracket_low, settings);
  ASSERT_TRUE(below.settled()) << variant.name << " x" << factor << ": " << below.reason;
  const StepOutcome above =
      classify_step(s.model, below.final_state, *s.found.row.bracket_low, *s.found.row.bracket_high, settings);
  EXPECT_FALSE(above.settled()) << variant.name << " x" << factor << ": " << above.reason;
}

const DetectorVariant kVariants[] = {
    {"slowdown_factor", [](RunawaySettings& r, double f) { r.slowdown_factor *= f; }},
    {"acceleration_factor", [](RunawaySettings& r, double f) { r.acceleration_factor *= f; }},
    {"horizon_multiple", [](RunawaySettings& r, double f) { r.horizon_multiple *= f; }},
    {"closeness", [](RunawaySettings& r, double f) { r.closeness *= f; }},
    {"relaxation_iterations", [](RunawaySettings& r, double f) { r.relaxation_iterations = int(r.relaxation_iterations * f); }},
    {"relative_tolerance", [](RunawaySettings& r, double f) { r.transient.relative_tolerance *= f; }},
    {"absolute_tolerance", [](RunawaySettings& r, double f) { r.transient.absolute_tolerance *= f; }},
    {"newton_tolerance", [](RunawaySettings& r, double f) { r.newton.residual_tolerance *= f; }},
    {"relative_width", [](RunawaySettings& r, double f) { r.relative_width *= f; }},
};

INSTANTIATE_TEST_SUITE_P(Bearing, DetectorRobustness,
                         ::testing::Combine(::testing::ValuesIn(kVariants), ::testing::Values(0.5, 2.0)),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param).name) +
                                  (std::get<1>(info.param) < 1 ? "_halved" : "_doubled");
                         });

// Oil fed under pressure lifts the gear off a light enough load, which has no steady
// state: the check of the start's branch goes down only to a light load that has one
// (the lightest of a tenth, a fifth, ... of the start), so the search still says which
// branch it started on. Before, it stopped at a tenth and said it could not check.
TEST(DistressSearchWithSupply, TheStartsBranchIsCheckedAboveTheLoadTheSupplyLifts) {
  Scene s = coarse_scene(545.0);
  testing::use_four_grooves(s);
  s.lubricant.supply = OilSupply{1e5, SupplyInlet::both};
  BearingModel model(s);
  // A tenth of the start is below what the supply lifts: no steady state there.
  model.set_load(8.0);
  std::vector<double> u;
  ASSERT_FALSE(SteadySolver(model, newton_settings(s)).solve_cold(u).converged);
  DistressSearchSettings settings;
  settings.load_start = 80.0;
  settings.load_end = 160.0;
  settings.bracket_width = 0.002;
  const DistressSearch found = search_distress(model, settings, {});
  EXPECT_FALSE(found.failed) << found.message;
  EXPECT_EQ(found.row.method.find("could not be checked"), std::string::npos) << found.row.method;
}

}  // namespace
}  // namespace twb
