// The public Bearing (twb/bearing.h, docs/api.md) on the coarse Table 1 mesh: a cold
// point is exactly the point study's state, a warm-started point the same steady state
// within what the solver's tolerance allows, whatever load the scene names, and the
// unknowns listed are the model's.
#include <gtest/gtest.h>

#include <numeric>

#include "../support/converged_balances.h"
#include "../support/table1_scene.h"
#include "twb/bearing.h"

namespace twb {
namespace {

Scene coarse_point(double load) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, load);
  testing::use_coarse_mesh(s);
  s.study.settings = PointSettings{};
  return s;
}

// The first solve starts cold, exactly as the point study does: the same code path, so
// the same numbers to the last bit.
TEST(BearingTest, ColdPointIsThePointStudysState) {
  Bearing study_bearing(coarse_point(120.0));
  const StudyOutcome study = study_bearing.run_study();
  ASSERT_EQ(study.states.size(), 1u);
  Bearing bearing(coarse_point(120.0));
  const SolvedState s = bearing.solve(120.0, 545.0);
  EXPECT_EQ(s.state.load, study.states[0].state.load);
  EXPECT_EQ(s.state.f_eff, study.states[0].state.f_eff);
  EXPECT_EQ(s.state.hmin_over_sigma, study.states[0].state.hmin_over_sigma);
  EXPECT_EQ(s.state.washer_mean_temperature, study.states[0].state.washer_mean_temperature);
  EXPECT_EQ(s.iterations, study.states[0].iterations);
  testing::expect_balanced(s.state);
}

// From the state at 100 N, the state at 120 N is the cold start's steady state: Newton
// stops at a scaled residual of 1e-10, and on this well-conditioned cool branch the
// reported quantities then agree to far better than 1e-7 (relative); a warm start that
// converged to another branch, or not at all, would differ in the first digits. It also
// takes fewer iterations than the pseudo-time march from cold.
TEST(BearingTest, WarmStartReachesTheSameState) {
  Bearing cold(coarse_point(120.0));
  const SolvedState reference = cold.solve(120.0, 545.0);
  Bearing warm(coarse_point(120.0));
  warm.solve(100.0, 545.0);
  const SolvedState s = warm.solve(120.0, 545.0);
  EXPECT_NEAR(s.state.f_eff, reference.state.f_eff, 1e-7 * reference.state.f_eff);
  EXPECT_NEAR(s.state.hmin_over_sigma, reference.state.hmin_over_sigma, 1e-7 * reference.state.hmin_over_sigma);
  EXPECT_NEAR(s.state.washer_mean_temperature, reference.state.washer_mean_temperature, 1e-7);
  EXPECT_LT(s.iterations, reference.iterations);
  testing::expect_balanced(s.state);
}

// solve() moves the bearing to the operating point asked for and back: the study that
// follows runs at the scene's load and speed, exactly as a fresh Bearing's.
TEST(BearingTest, StudyAfterPointsIsTheScenes) {
  Scene s = coarse_point(120.0);
  Bearing fresh(s);
  const StudyOutcome expected = fresh.run_study();
  Bearing used(s);
  used.solve(90.0, 300.0);
  EXPECT_EQ(used.scene().operating.speed, 545.0);
  const StudyOutcome study = used.run_study();
  ASSERT_EQ(study.states.size(), 1u);
  EXPECT_EQ(study.states[0].state.load, expected.states[0].state.load);
  EXPECT_EQ(study.states[0].state.speed, expected.states[0].state.speed);
  EXPECT_EQ(study.states[0].state.f_eff, expected.states[0].state.f_eff);
}

TEST(BearingTest, UnknownsAreTheEffectsBlocks) {
  Bearing full(coarse_point(120.0));
  const auto blocks = full.unknowns();
  const long total = std::accumulate(blocks.begin(), blocks.end(), 0L,
                                     [](long n, const UnknownBlock& b) { return n + long(b.size); });
  EXPECT_EQ(total, full.unknown_count());
  EXPECT_TRUE(std::any_of(blocks.begin(), blocks.end(), [](const UnknownBlock& b) { return b.effect == BlockEffect::thermal; }));
  EXPECT_GT(full.jacobian_nonzeros(), full.unknown_count());

  Scene isothermal = coarse_point(120.0);
  isothermal.effects.thermal = false;
  const Bearing cold_oil(isothermal);
  for (const UnknownBlock& b : cold_oil.unknowns()) EXPECT_NE(b.effect, BlockEffect::thermal) << b.name;
  EXPECT_LT(cold_oil.unknown_count(), full.unknown_count());
}

// The scene's load and speed are where its study starts; a point asked for at another
// load is that load's steady state (the model's scales, which the scene's load sets,
// change only the path Newton takes, so the states agree to the solver's tolerance).
TEST(BearingTest, PointDoesNotDependOnTheScenesLoad) {
  Bearing here(coarse_point(120.0));
  Bearing elsewhere(coarse_point(500.0));
  const SolvedState a = here.solve(120.0, 545.0);
  const SolvedState b = elsewhere.solve(120.0, 545.0);
  EXPECT_EQ(b.state.load, 120.0);
  EXPECT_NEAR(b.state.f_eff, a.state.f_eff, 1e-7 * a.state.f_eff);
  EXPECT_NEAR(b.state.hmin_over_sigma, a.state.hmin_over_sigma, 1e-7 * a.state.hmin_over_sigma);
  EXPECT_NEAR(b.state.washer_mean_temperature, a.state.washer_mean_temperature, 1e-7);
}

}  // namespace
}  // namespace twb
