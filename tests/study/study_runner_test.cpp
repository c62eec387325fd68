// The study runner's multi-run studies on a coarse mesh (5 × 24 nodes, seconds each):
// a load sweep over several speeds and a second parameter, and the choice of the
// sliding film (docs/physics.md section 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "../support/table1_scene.h"
#include "study/study_runner.h"

namespace twb {
namespace {

// 100, 200 and 300 N: at 545 rad/s distress lies between 100 and 200 N on this mesh
// (near 161 N), so the grid holds the cool branch, the runaway and the hot branch.
Scene coarse_grid(StudyType type, std::vector<double> speeds) {
  Scene s = testing::table1_scene(true, true, true, true, speeds.front(), 100.0);
  testing::use_coarse_mesh(s);
  LoadGrid grid;
  grid.loads = {100.0, 300.0};
  grid.load_steps = 3;
  grid.speeds = std::move(speeds);
  s.study.settings = default_settings(type);
  if (auto* sweep = std::get_if<LoadSweepSettings>(&s.study.settings)) sweep->grid = grid;
  if (auto* choice = std::get_if<SlidingChoiceSettings>(&s.study.settings)) choice->grid = grid;
  if (auto* map = std::get_if<DistressMapSettings>(&s.study.settings)) {
    map->search = grid;  // (a map searches its range: no grid)
    map->speeds = grid.speeds;
  }
  return s;
}

// A map's settings (the scene's study is one).
DistressMapSettings& map_of(Scene& s) { return std::get<DistressMapSettings>(s.study.settings); }

// The bracket's relative width: W_d is known to within it.
double scene_bracket_width() { return FailureSearch{}.bracket_width; }

StudyOutcome run(const Scene& scene) {
  BearingModel model(scene);
  return run_study(model, {});
}

bool on_grid(double load) {
  return std::abs(load - 100.0) < 1e-9 || std::abs(load - 200.0) < 1e-9 || std::abs(load - 300.0) < 1e-9;
}

// Every state says its speed; each speed reaches every load of the grid; one distress
// row per speed, in the order of the list; the runaway trajectory belongs to the speed
// that ran away.
TEST(StudyRunner, LoadSweepOverSpeeds) {
  const StudyOutcome out = run(coarse_grid(StudyType::load_sweep, {136.0, 545.0}));
  ASSERT_FALSE(out.solver_failed) << out.message;
  EXPECT_TRUE(out.parameter_columns.empty());
  for (double speed : {136.0, 545.0}) {
    int grid_states = 0;
    for (const SolvedState& s : out.states)
      if (s.state.speed == speed && on_grid(s.state.load)) ++grid_states;
    EXPECT_EQ(grid_states, 3) << speed << " rad/s";
  }
  for (const SolvedState& s : out.states) EXPECT_TRUE(s.state.speed == 136.0 || s.state.speed == 545.0);
  ASSERT_EQ(out.distress.size(), 2u);
  EXPECT_EQ(out.distress[0].speed, 136.0);
  EXPECT_EQ(out.distress[1].speed, 545.0);
  EXPECT_FALSE(out.distress[0].distress_load) << out.distress[0].method;  // gradual heating, no fold
  ASSERT_TRUE(out.distress[1].distress_load) << out.distress[1].method;
  EXPECT_GT(*out.distress[1].distress_load, 100.0);
  EXPECT_LT(*out.distress[1].distress_load, 200.0);
  ASSERT_FALSE(out.trajectory.empty());
  for (const TrajectorySample& t : out.trajectory) EXPECT_EQ(t.state.speed, 545.0);
  // Each state names its branch: at 136 rad/s (no fold) every state is on the cool one;
  // at 545 rad/s the cool states lie below W_d and the hot ones, where the runaway
  // settled and the sweep went on, above it, and the hot branch carries far more of
  // the load on contact than the cool one did at a lighter load.
  const double w_d = *out.distress[1].distress_load;
  int hot = 0;
  for (const SolvedState& s : out.states) {
    if (s.state.speed == 136.0) {
      EXPECT_EQ(s.branch, Branch::cool) << s.state.load;
    }
    if (s.state.speed != 545.0) continue;
    ASSERT_TRUE(s.branch == Branch::cool || s.branch == Branch::hot) << branch_name(s.branch);
    if (s.branch == Branch::cool) {
      EXPECT_LT(s.state.load, w_d * (1 + scene_bracket_width()));
    }
    if (s.branch == Branch::hot) {
      ++hot;
      EXPECT_GT(s.state.load, w_d * (1 - scene_bracket_width()));
      EXPECT_GT(s.state.contact_share, 0.5);
    }
  }
  EXPECT_GE(hot, 2) << "200 N and 300 N lie past distress";
}

// The second parameter tags every state, row and sample with its value; at 136 rad/s,
// where asperities carry much of the load, the larger dry friction coefficient gives
// the larger torque at every load.
TEST(StudyRunner, LoadSweepOverAParameter) {
  Scene scene = coarse_grid(StudyType::load_sweep, {136.0});
  scene.friction.law = FrictionLaw::constant;
  std::get<LoadSweepSettings>(scene.study.settings).axes = {
      MapAxis{.parameter = MapParameter::friction_coefficient, .path = {}, .unit = {}, .values = {0.05, 0.2}}};
  const StudyOutcome out = run(scene);
  ASSERT_FALSE(out.solver_failed) << out.message;
  EXPECT_EQ(out.parameter_columns, std::vector<std::string>{"friction_coefficient"});
  ASSERT_EQ(out.distress.size(), 2u);
  EXPECT_EQ(out.distress[0].parameters, std::vector<double>{0.05});
  EXPECT_EQ(out.distress[1].parameters, std::vector<double>{0.2});
  for (double load : {100.0, 200.0, 300.0}) {
    double torque[2] = {-1, -1};
    for (const SolvedState& s : out.states) {
      ASSERT_EQ(s.parameters.size(), 1u);
      ASSERT_TRUE(s.parameters[0] == 0.05 || s.parameters[0] == 0.2);
      if (std::abs(s.state.load - load) < 1e-9) torque[s.parameters[0] == 0.2] = s.state.torque;
    }
    ASSERT_GT(torque[0], 0.0) << load << " N";
    EXPECT_GT(torque[1], torque[0]) << load << " N";
  }
}

// Which film slides: both configurations at every grid load, the one of lower torque
// chosen and kept in states; the sliding film's area is its annulus, the washer's for
// film 1 (11.1-22.7 mm) and the washer-gear overlap for film 2 (15.6-22.7 mm).
TEST(StudyRunner, SlidingChoiceKeepsTheLowerTorque) {
  const StudyOutcome out = run(coarse_grid(StudyType::sliding_choice, {545.0}));
  ASSERT_FALSE(out.solver_failed) << out.message;
  EXPECT_TRUE(out.sliding_column);
  ASSERT_EQ(out.distress.size(), 2u);
  EXPECT_EQ(out.distress[0].sliding, SlidingFilm::carrier_washer);
  EXPECT_EQ(out.distress[1].sliding, SlidingFilm::washer_gear);
  const std::vector<SlidingRow>& both = std::get<SlidingChoiceOutcome>(out.own).rows;
  ASSERT_EQ(both.size(), 6u);  // 3 loads × 2 configurations
  ASSERT_EQ(out.states.size(), 3u);
  const double pi = std::numbers::pi;
  const double film1 = pi / 4 * (22.7e-3 * 22.7e-3 - 11.1e-3 * 11.1e-3);
  const double film2 = pi / 4 * (22.7e-3 * 22.7e-3 - 15.6e-3 * 15.6e-3);
  for (std::size_t k = 0; k < 3; ++k) {
    const SlidingRow& a = both[2 * k];
    const SlidingRow& b = both[2 * k + 1];
    EXPECT_EQ(a.solved.sliding, SlidingFilm::carrier_washer);
    EXPECT_EQ(b.solved.sliding, SlidingFilm::washer_gear);
    EXPECT_EQ(a.solved.state.load, b.solved.state.load);
    EXPECT_NEAR(a.film_area, film1, 1e-12 * film1);
    EXPECT_NEAR(b.film_area, film2, 1e-12 * film2);
    EXPECT_NE(a.chosen, b.chosen);
    const SlidingRow& chosen = a.chosen ? a : b;
    EXPECT_LE(chosen.solved.state.torque, (a.chosen ? b : a).solved.state.torque);
    EXPECT_EQ(out.states[k].sliding, chosen.solved.sliding);
    EXPECT_EQ(out.states[k].state.torque, chosen.solved.state.torque);
  }
  // The paper's 31 %: the gear face alone is 30.6 % smaller than the washer (the washer
  // is 44 % larger than the gear face); film 1 lifts more at the light load.
  EXPECT_NEAR((film1 - film2) / film1, 0.31, 0.005);
  EXPECT_GT(both[0].solved.state.fluid_force, both[1].solved.state.fluid_force);
}

// Independent searches on several threads give the same study: every number written
// (the timing column wall_ms aside) and the order of rows, whatever the thread count. A
// distress map over three speeds and two friction coefficients (six searches of unequal
// length: with and without a fold) on one, two and four threads.
TEST(StudyRunner, ThreadsGiveTheSameResults) {
  Scene scene = coarse_grid(StudyType::distress_map, {136.0, 545.0, 953.0});
  scene.friction.law = FrictionLaw::constant;
  map_of(scene).axes = {MapAxis{.parameter = MapParameter::friction_coefficient, .path = {}, .unit = {}, .values = {0.2, 0.3}}};
  map_of(scene).error_bars.estimate = ErrorEstimate::none;
  auto outcome = [&](int threads) {
    BearingModel model(scene);
    StudyOutcome out = run_study(model, {}, RunOptions{.threads = threads});
    for (SolvedState& s : out.states) s.wall_ms = 0.0;
    return std::pair{distress_csv(out.distress, out.parameter_columns), states_csv(out.states, out.parameter_columns)};
  };
  const auto one = outcome(1);
  ASSERT_NE(one.first.find("545,0.2,"), std::string::npos) << one.first;
  for (const int threads : {2, 4}) {
    const auto many = outcome(threads);
    EXPECT_EQ(many.first, one.first) << threads << " threads";
    EXPECT_EQ(many.second, one.second) << threads << " threads";
  }
}

// One search on two threads lends the idle one: to the check of its start's branch
// beside the search, and to its error bars (W_d's fold and each criterion's crossing,
// each on its own refined model). The results, and so every number written, are those of
// one thread, and so is the work counted. At 545 rad/s on this mesh the search proves a
// fold and, with a flash point of 37 degC, crosses that criterion before it (both kinds
// of bar run); at 136 rad/s it finds no fold up to 300 N, and the start's check, run
// beside the search, is used.
TEST(StudyRunner, ASearchOnLentThreadsIsTheSameAsOnOne) {
  for (const double speed : {545.0, 136.0}) {
    Scene scene = coarse_grid(StudyType::distress_map, {speed});
    map_of(scene).error_bars.estimate = ErrorEstimate::richardson;
    scene.lubricant.flash_temperature = 310.15;
    auto outcome = [&](int threads) {
      BearingModel model(scene);
      StudyOutcome out = run_study(model, {}, RunOptions{.threads = threads});
      for (SolvedState& s : out.states) s.wall_ms = 0.0;
      return out;
    };
    const StudyOutcome one = outcome(1);
    ASSERT_EQ(one.distress.size(), 1u);
    const DistressRow& row = one.distress.front();
    if (speed == 545.0) {
      std::size_t crossing_bars = 0;
      for (const auto& e : row.criterion_errors) crossing_bars += e.has_value();
      ASSERT_GE(crossing_bars, 1u) << row.method;
      ASSERT_TRUE(row.discretization_error.has_value()) << row.method;
    } else {
      ASSERT_FALSE(row.distress_load.has_value()) << row.method;
    }
    const StudyOutcome two = outcome(2);
    EXPECT_EQ(distress_csv(two.distress, two.parameter_columns), distress_csv(one.distress, one.parameter_columns))
        << speed;
    EXPECT_EQ(states_csv(two.states, two.parameter_columns), states_csv(one.states, one.parameter_columns)) << speed;
    EXPECT_EQ(two.timings.klu_factorizations, one.timings.klu_factorizations) << speed;
  }
}

}  // namespace
}  // namespace twb
