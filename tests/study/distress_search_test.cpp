// Distress on the bearing (MODEL.md section 8), on a coarse mesh so it runs in CI: the
// load bracketed by transients agrees with the fold of the steady branch, steps just
// below it settle and just above it run away.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/table1_scene.h"
#include "twb/solver/runaway.h"
#include "twb/study/distress_search.h"

namespace twb {
namespace {

// 5 radial × 24 circumferential nodes: the fold moves with the mesh, but the transient
// and the continuation see the same discrete system, so they must agree on it.
Scene coarse_scene(double speed) {
  Scene s = testing::table1_scene(true, true, true, true, speed, 100.0);
  s.mesh.radial_nodes = 5;
  s.mesh.circumferential_nodes = 24;
  return s;
}

class BearingDistress : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new BearingModel(coarse_scene(545.0));
    DistressSearchSettings settings;
    settings.load_start = 100.0;
    settings.load_end = 600.0;
    settings.bracket_width = 0.002;
    found_ = new DistressSearch(search_distress(*model_, settings, {}));
  }
  static void TearDownTestSuite() {
    delete found_;
    delete model_;
  }
  static BearingModel* model_;
  static DistressSearch* found_;
};
BearingModel* BearingDistress::model_ = nullptr;
DistressSearch* BearingDistress::found_ = nullptr;

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

// 1 % either side of W_d: from the steady state at the bracket's low load, the step
// below settles on a steady state and the step above runs away.
TEST_F(BearingDistress, StepBelowSettlesStepAboveRunsAway) {
  ASSERT_TRUE(found_->row.distress_load);
  const double wd = *found_->row.distress_load, low = *found_->row.bracket_low;
  RunawaySettings settings;
  model_->set_load(low);
  const StepOutcome below = classify_step(*model_, found_->bracket_state, 0.99 * wd, settings);
  EXPECT_TRUE(below.settled()) << below.reason;
  model_->set_load(low);
  const StepOutcome above = classify_step(*model_, found_->bracket_state, 1.01 * wd, settings);
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

}  // namespace
}  // namespace twb
