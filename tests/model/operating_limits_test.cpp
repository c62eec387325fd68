// The limits a state reports besides distress (model/operating_limits.h): each one set
// off exactly above its threshold, from the scene's own values, and on solved states of
// the paper's bearing where the physics says it must be.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "model/limit_thresholds.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "twb/results/limit_notes.h"
#include "twb/results/run_axes.h"
#include "twb/study/study_outcome.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

bool has(const std::vector<LimitExcess>& limits, LimitKind kind) {
  return std::any_of(limits.begin(), limits.end(), [&](const LimitExcess& e) { return e.kind == kind; });
}

TEST(OperatingLimits, EachIsExceededOnlyAboveItsThreshold) {
  OperatingLimits l;
  l.max_oil_temperature = 423.15;
  l.flash_point = 453.15;
  l.hardness = 1e9;
  const auto values = [](double mean, double peak, double pressure, double film) {
    LimitValues v;
    v.washer_mean_temperature = mean, v.oil_peak_temperature = peak, v.max_contact_pressure = pressure;
    v.hmin_over_sigma = film, v.thermal = true;
    return v;
  };
  LimitValues at = values(423.15, 453.15, 1e9, 0.5);
  EXPECT_TRUE(exceeded_limits(at, l).empty()) << "a value at its limit is within it";
  LimitValues past = values(423.16, 453.16, 1.0001e9, 0.4999);
  const std::vector<LimitExcess> all = exceeded_limits(past, l);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(limit_names(all), "oil_temperature;oil_peak_temperature;contact_pressure;film_below_statistics");
  EXPECT_DOUBLE_EQ(all[2].value, 1.0001e9);
  EXPECT_DOUBLE_EQ(all[2].limit, 1e9);
  // Without the thermal effect every temperature is the ambient by construction, and
  // without contact there is no hardness to exceed.
  past.thermal = false;
  l.hardness = 0.0;
  EXPECT_EQ(limit_names(exceeded_limits(past, l)), "film_below_statistics");
  // Classic Reynolds (no contact, no flow factors) has no statistical range to leave.
  l.statistical = false;
  EXPECT_TRUE(exceeded_limits(past, l).empty());
}

// PV (physics §8): the sliding film's contact force over the washer's area times the
// sliding speed at its mean radius, against the washer's limit; a failure criterion whose
// margin is the limit less the PV, none without a limit; nothing at rest.
TEST(OperatingLimits, ThePVOfTheSlidingFaceAgainstTheWashersLimit) {
  Scene scene = testing::table1_scene(true, true, true, true, 545.0, 100.0);
  scene.washer.material.pv_limit = 1.5e6;
  const OperatingLimits l = OperatingLimits::of(scene);
  const double ri = scene.washer.inner_radius, ro = scene.washer.outer_radius;
  const double area = std::numbers::pi * (ro * ro - ri * ri), speed = 545.0 * 0.5 * (ri + ro);
  LimitValues v;
  v.contact_force = 1.5e6 * area / speed;  // on the limit
  v.speed = -545.0;                         // either sense of rotation
  EXPECT_NEAR(v.pv(l), 1.5e6, 1e-9 * 1.5e6);
  EXPECT_NEAR(*failure_margin(LimitKind::pv, v, l), 0.0, 1e-9 * 1.5e6);
  EXPECT_FALSE(has(exceeded_limits(v, l), LimitKind::pv)) << "a value at its limit is within it";
  v.contact_force *= 1.001;
  const std::vector<LimitExcess> past = exceeded_limits(v, l);
  ASSERT_TRUE(has(past, LimitKind::pv));
  EXPECT_NE(describe_limit(past.back()).find("materials.washer.pv_limit"), std::string::npos);
  EXPECT_TRUE(is_failure_criterion(LimitKind::pv));
  v.speed = 0.0;
  EXPECT_DOUBLE_EQ(*failure_margin(LimitKind::pv, v, l), 1.5e6);
  scene.washer.material.pv_limit.reset();
  EXPECT_FALSE(failure_margin(LimitKind::pv, v, OperatingLimits::of(scene)));
}

// Scuffing (physics §8): the asperities' hottest contact against the pair's scuffing
// temperature, applied wherever the contact model is on (its default 224 degC), and not
// without it; a state without contacts has no contact temperature and no margin.
TEST(OperatingLimits, ScuffingIsTheContactTemperatureAgainstThePairs) {
  Scene scene = testing::table1_scene(true, true, true, true, 545.0, 100.0);
  const OperatingLimits l = OperatingLimits::of(scene);
  ASSERT_TRUE(l.scuffing_temperature);
  EXPECT_DOUBLE_EQ(*l.scuffing_temperature, 497.15);
  EXPECT_TRUE(criterion_applies(LimitKind::scuffing, l, true));
  LimitValues v;
  v.contact_temperature = 497.15;
  EXPECT_DOUBLE_EQ(*failure_margin(LimitKind::scuffing, v, l), 0.0);
  EXPECT_FALSE(has(exceeded_limits(v, l), LimitKind::scuffing)) << "a value at its limit is within it";
  v.contact_temperature = 500.0;
  const std::vector<LimitExcess> past = exceeded_limits(v, l);
  ASSERT_TRUE(has(past, LimitKind::scuffing));
  EXPECT_NE(describe_limit(past.back()).find("limits.scuffing_temperature"), std::string::npos);
  EXPECT_EQ(failure_names(past), "scuffing");
  v.contact_temperature.reset();
  EXPECT_FALSE(failure_margin(LimitKind::scuffing, v, l));
  scene.effects.asperity_contact = false;
  EXPECT_FALSE(criterion_applies(LimitKind::scuffing, OperatingLimits::of(scene), true));
}

// modulus_data:<body> (physics §23): a body whose material has a modulus curve is past
// its data where its hottest face is above the curve's last temperature, the modulus held
// there; the margin is that temperature less the face's, and a body without a curve (the
// steel carrier and gear here) has no such criterion.
TEST(OperatingLimits, ABodyBeyondItsModulusDataIsPastTheirCriterion) {
  Scene scene = testing::table1_scene(true, true, true, true, 545.0, 100.0);
  scene.washer.material.modulus_by_temperature = {{296.15, 3.7e9}, {423.15, 3.0e9}, {473.15, 0.45e9}};
  const OperatingLimits l = OperatingLimits::of(scene);
  EXPECT_TRUE(criterion_applies(LimitKind::washer_modulus_data, l, true));
  EXPECT_FALSE(criterion_applies(LimitKind::washer_modulus_data, l, false)) << "no temperatures to be beyond";
  EXPECT_FALSE(criterion_applies(LimitKind::carrier_modulus_data, l, true));
  EXPECT_FALSE(criterion_applies(LimitKind::gear_modulus_data, l, true));
  LimitValues v;
  v.thermal = true;
  v.body_temperature = {500.0, 473.15, 500.0};
  EXPECT_DOUBLE_EQ(*failure_margin(LimitKind::washer_modulus_data, v, l), 0.0);
  EXPECT_FALSE(has(exceeded_limits(v, l), LimitKind::washer_modulus_data)) << "the data's last point is within them";
  v.body_temperature[1] = 480.0;
  EXPECT_DOUBLE_EQ(*failure_margin(LimitKind::washer_modulus_data, v, l), 473.15 - 480.0);
  const std::vector<LimitExcess> past = exceeded_limits(v, l);
  ASSERT_TRUE(has(past, LimitKind::washer_modulus_data));
  EXPECT_EQ(failure_names(past), "modulus_data:washer");
  EXPECT_NE(describe_limit(past.back()).find("materials.washer.modulus_by_temperature"), std::string::npos)
      << describe_limit(past.back());
  // The material's own temperature limit is a criterion of its own, beside it.
  scene.washer.material.max_temperature = 523.15;
  const OperatingLimits both = OperatingLimits::of(scene);
  EXPECT_DOUBLE_EQ(*failure_margin(LimitKind::washer_temperature, v, both), 523.15 - 480.0);
  EXPECT_DOUBLE_EQ(*failure_margin(LimitKind::washer_modulus_data, v, both), 473.15 - 480.0);
}

TEST(OperatingLimits, HardnessIsThatOfTheSoftestFace) {
  Scene s = testing::table1_scene(true, true, true, true);
  s.washer.material.yield_strength = 400e6;
  const OperatingLimits l = OperatingLimits::of(s);
  EXPECT_DOUBLE_EQ(l.hardness, 2.84 * 400e6);
  EXPECT_DOUBLE_EQ(l.max_oil_temperature, s.lubricant.max_temperature);
  s.effects.asperity_contact = false;
  EXPECT_EQ(OperatingLimits::of(s).hardness, 0.0);
}

BearingState solved(Scene scene) {
  scene.mesh.radial_nodes = 5;
  scene.mesh.circumferential_nodes = 24;
  BearingModel m(scene);
  std::vector<double> u;
  const SteadyReport rep = SteadySolver(m, {}).solve_cold(u);
  EXPECT_TRUE(rep.converged) << rep.message;
  return m.describe(u);
}

// The paper's bearing at 545 rad/s: a full film at 100 N, within every limit; at 500 N
// on its hot branch (the README's one-point example), the washer above 150 degC and the
// film above the flash point.
TEST(OperatingLimits, ThePapersBearingExceedsTheOilsLimitsOnlyOnItsHotBranch) {
  const BearingState cool = solved(testing::table1_scene(true, true, true, true, 545.0, 100.0));
  EXPECT_TRUE(cool.limits.empty()) << limit_names(cool.limits);
  const BearingState hot = solved(testing::table1_scene(true, true, true, true, 545.0, 500.0));
  EXPECT_TRUE(has(hot.limits, LimitKind::oil_temperature)) << limit_names(hot.limits);
  EXPECT_TRUE(has(hot.limits, LimitKind::oil_peak_temperature)) << limit_names(hot.limits);
}

// At rest under a heavy load the washer sits on its summits: the film closes below the
// statistical model's range and the rim's contact pressure passes the hardness.
TEST(OperatingLimits, AHeavyLoadAtRestCrushesTheSummits) {
  const BearingState s = solved(testing::table1_scene(false, false, true, false, 0.0, 50000.0));
  EXPECT_TRUE(has(s.limits, LimitKind::film_below_statistics)) << limit_names(s.limits);
  EXPECT_TRUE(has(s.limits, LimitKind::contact_pressure)) << limit_names(s.limits);
  EXPECT_GT(s.max_contact_pressure, OperatingLimits::of(testing::table1_scene(false, false, true, false)).hardness);
}

// The summary names, per run, the lightest load past each limit, and says so when that
// state is on the cool branch below W_d.
TEST(LimitNotes, SayWhenTheCoolBranchLeavesTheModelBeforeDistress) {
  SolvedState a, b;
  a.converged = b.converged = true;
  a.state.speed = b.state.speed = 545.0;
  a.branch = b.branch = Branch::cool;
  a.state.load = 150.0;
  b.state.load = 120.0;
  a.state.limits = b.state.limits = {{LimitKind::oil_temperature, 430.0, 423.15}};
  DistressRow d;
  d.speed = 545.0;
  d.distress_load = 188.4;
  const std::vector<std::string> lines = limit_notes({a, b}, {d});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("oil_temperature from 120 N"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("below W_d = 188.40 N"), std::string::npos) << lines[0];
  a.branch = b.branch = Branch::hot;
  EXPECT_EQ(limit_notes({a, b}, {d})[0].find("below W_d"), std::string::npos);
  EXPECT_TRUE(limit_notes({}, {d}).empty());
  // A run of a map's second axis is named by its column.
  a.parameters = b.parameters = d.parameters = {4.0};
  const std::vector<std::string> named = limit_notes({a, b}, {d}, {"groove_count"});
  ASSERT_EQ(named.size(), 1u);
  EXPECT_NE(named[0].find("at 545 rad/s, groove_count = 4:"), std::string::npos) << named[0];
}

// A scene that gave its speeds in rpm reads them back in rpm: the limit notes and the
// summary's distress and failure lines (a new user who wrote 4000 rpm read 418.879
// rad/s). 4000 rpm = 4000·2π/60 rad/s, and back to six digits.
TEST(LimitNotes, SpeedsGivenInRpmAreSaidInRpm) {
  const double speed = 4000.0 * 2.0 * std::numbers::pi / 60.0;
  SolvedState a;
  a.converged = true;
  a.state.speed = speed;
  a.state.load = 350.0;
  a.state.limits = {{LimitKind::oil_temperature, 430.0, 423.15}};
  DistressRow d;
  d.speed = speed;
  d.failure = "fails at 350 N";
  const std::vector<std::string> in_rpm = limit_notes({a}, {d}, {}, true), in_rad_s = limit_notes({a}, {d});
  ASSERT_EQ(in_rpm.size(), 1u);
  ASSERT_EQ(in_rad_s.size(), 1u);
  EXPECT_NE(in_rpm[0].find("limit at 4000 rpm: "), std::string::npos) << in_rpm[0];
  EXPECT_NE(in_rad_s[0].find("limit at 418.879 rad/s: "), std::string::npos) << in_rad_s[0];
  StudyOutcome outcome;
  outcome.distress = {d};
  outcome.speeds_in_rpm = true;
  const std::vector<std::string> lines = summary_lines(outcome);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("distress at 4000 rpm: ", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1], "failure at 4000 rpm: fails at 350 N");
  EXPECT_EQ(speed_text(545.0, false), "545 rad/s");
}

}  // namespace
}  // namespace twb
