// A washer's life in the wear's slow time (study type life, docs/physics.md section 20):
// the disc clutch's uniform wear reached from the new washer's uniform pressure, the
// wear allowance located where the deepest face reaches it, and the depths' error under
// IDA's control.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "model/bearing_model.h"
#include "study/searches/distress_search.h"
#include "study/study_runner.h"
#include "study/time/life_march.h"
#include "twb/results/worn_washer.h"
#include "twb/scene/scene_loader.h"
#include "twb/study/study_outcome.h"

namespace twb {
namespace {

// The paper's washer with wear (configs/effects/wear.yaml) on a coarse mesh, as a life.
Scene life_scene(const std::string& study, const std::vector<std::string>& more = {}) {
  std::vector<std::string> overrides{"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "study=" + study};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/effects/wear.yaml", overrides);
}

const std::vector<LifeRow>& rows_of(const StudyOutcome& out) { return std::get<LifeOutcome>(out.own).rows; }

// A states.csv column of a recorded state.
std::optional<double> out_state_value(const SolvedState& s, const std::string& column) {
  const ResultTable t = states_table({s});
  for (const ResultColumn& c : t.columns())
    if (c.name == column) return c.numbers.front();
  return std::nullopt;
}

StudyOutcome lived(const Scene& s) {
  BearingModel model(s);
  StudyOutcome out = run_study(model, {});
  EXPECT_FALSE(out.solver_failed) << out.message;
  EXPECT_FALSE(rows_of(out).empty());
  return out;
}

// A flat washer on its asperities alone (no tilt, no film pressure, a constant friction
// coefficient): new, it presses uniformly and its friction torque is
// (2/3)·f·W·(r_o³ − r_i³)/(r_o² − r_i²); worn in, every radius wears at the same rate, so
// p·r is constant and the torque f·W·(r_o + r_i)/2, the uniform wear of disc clutches
// (physics §20's check). What else acts: the oil's shear at the least viscosity a scene
// takes (1e-6 Pa·s) adds about 2e-5 of the torque, and the depths' lumped rates err by
// O(Δr²), about 5e-6 of it on 5 radial nodes: 5e-5 bounds both.
TEST(Life, AFlatWasherInContactWearsFromUniformPressureToUniformWear) {
  const Scene s = life_scene("{type: life, duration: 20 h, tolerance: 0.001 um, report_every: 2 h, failure_load: false}",
                             {"effects=[asperity_contact, wear]", "geometry.gear.tilt=0 mrad",
                              "friction={law: constant, coefficient: 0.1}",
                              "lubricant.viscosity={model: constant, value: 1e-6 Pa s}", "operating.load=300 N",
                              "surfaces.carrier.wear_rate=1e-15 m^3/(N m)", "surfaces.washer.wear_rate=1e-15 m^3/(N m)",
                              "limits.wear_depth=0.5 mm"});
  const StudyOutcome out = lived(s);
  const std::vector<LifeRow>& rows = rows_of(out);
  const double ri = s.washer.inner_radius, ro = s.washer.outer_radius, fw = 0.1 * s.operating.load;
  const double uniform_pressure = fw * 2.0 / 3.0 * (ro * ro * ro - ri * ri * ri) / (ro * ro - ri * ri);
  const double uniform_wear = fw * (ro + ri) / 2.0;
  EXPECT_NEAR(rows.front().torque, uniform_pressure, 5e-5 * uniform_pressure);
  EXPECT_NEAR(rows.back().torque, uniform_wear, 5e-5 * uniform_wear);
  EXPECT_EQ(rows.back().event, "end");
  // Worn in, the deepest point wears as fast as the mean: the shape no longer changes.
  const LifeRow& before = rows[rows.size() - 2];
  const double deepest_rate = (rows.back().rest.deepest - before.rest.deepest);
  const double mean_rate = (rows.back().rest.mean - before.rest.mean);
  EXPECT_NEAR(deepest_rate, mean_rate, 1e-6 * mean_rate);
}

// A gear tilted by γ over a washer, in contact alone (the flat washer's test above, film 2
// sliding: the washer's face at rest in the load frame, the gear's turning over it): the
// face at rest wears where the tilt presses it until its worn face lies in the tilt's plane
// (conformity), its depth's first circumferential harmonic at each radius the relative tilt
// times r; then the gap is the same round each radius and the faces wear uniformly (p·r
// constant), the torque the clutch's f·W·(r_o + r_i)/2 (physics §20). On the mesh the
// depths are bilinear between nodes while the plane is exact at every point: conforming on
// average over each cell takes the nodes' harmonic (sin x/x)/cos x larger, x = Δθ/2
// (1.0057 on 24 nodes), which the test expects; how the contact weights the chord's
// remaining O(x²) departure from the plane within a cell moves it by O(x⁴) of itself
// (3e-4 here; measured 3e-5). IDA holds each depth to 0.1 nm, and the harmonic's weights
// 2/N·cos θ sum in magnitude below 2: 0.2 nm more. The torque within the flat washer's 5e-5.
TEST(Life, ATiltedGearWearsTheWasherIntoItsTiltAndThenWearsUniformly) {
  const double tilt = 1e-3;
  const Scene s = life_scene("{type: life, duration: 200 h, tolerance: 0.1 nm, report_every: 100 h, failure_load: false}",
                             {"effects=[asperity_contact, wear]", "geometry.gear.tilt=1 mrad",
                              "friction={law: constant, coefficient: 0.1}",
                              "lubricant.viscosity={model: constant, value: 1e-6 Pa s}", "operating.load=300 N",
                              "operating.sliding=washer_gear", "surfaces.washer.wear_rate=1e-17 m^3/(N m)",
                              "surfaces.gear.wear_rate=1e-17 m^3/(N m)", "limits.wear_depth=0.5 mm"});
  const StudyOutcome out = lived(s);
  const WornWasher& worn = std::get<LifeOutcome>(out.own).worn.back();
  const int nr = worn.radial_nodes, nt = worn.circumferential_nodes;
  // The relative tilt of film 2's faces: the gear's less the washer's own.
  const double gx = *out_state_value(out.states.back(), "gamma_x_ratio") * tilt;
  const double gy = *out_state_value(out.states.back(), "gamma_y_ratio") * tilt;
  const double relative = std::hypot(gx, tilt - gy);
  const double half_cell = std::numbers::pi / nt, on_nodes = std::sin(half_cell) / half_cell / std::cos(half_cell);
  for (int i = 0; i < nr; ++i) {
    const double r = worn.inner_radius + i * (worn.outer_radius - worn.inner_radius) / (nr - 1);
    double c = 0.0, s_ = 0.0;
    for (int j = 0; j < nt; ++j) {
      const double theta = 2.0 * std::numbers::pi * j / nt, d = worn.rest[std::size_t(i * nt + j)];
      c += 2.0 / nt * d * std::cos(theta);
      s_ += 2.0 / nt * d * std::sin(theta);
    }
    const double expected = relative * r * on_nodes;
    EXPECT_NEAR(std::hypot(c, s_), expected, std::pow(half_cell, 4) * expected + 0.2e-9) << "radius " << r;
  }
  const std::vector<LifeRow>& rows = rows_of(out);
  // (film 2's annulus: the worn washer's)
  const double uniform_wear = 0.1 * s.operating.load * (worn.outer_radius + worn.inner_radius) / 2.0;
  EXPECT_NEAR(rows.back().torque, uniform_wear, 5e-5 * uniform_wear);
}

// The life ends where the deepest face reaches limits.wear_depth: located between IDA's
// steps on its interpolant (to a millionth of the step) and the bearing solved again
// there, so the deepest depth is the allowance to a millionth of a step's wear.
TEST(Life, EndsWhereAFaceReachesTheWearAllowance) {
  const Scene s = life_scene("{type: life, duration: 1000 h, tolerance: 0.001 um, failure_load: false}",
                             {"operating.load=150 N", "limits.wear_depth=0.5 um"});
  const StudyOutcome out = lived(s);
  const LifeRow& last = rows_of(out).back();
  EXPECT_EQ(last.event, "wear_allowance");
  EXPECT_LT(last.time, 1000 * 3600.0);
  EXPECT_NEAR(std::max(last.rest.deepest, last.turn.deepest), 0.5e-6, 1e-9);
  for (std::size_t k = 0; k + 1 < rows_of(out).size(); ++k) EXPECT_LT(rows_of(out)[k].rest.deepest, 0.5e-6);
  EXPECT_EQ(out.states.size(), rows_of(out).size());
}

// study.tolerance bounds the depths' error at the end of the life (IDA's local tolerance
// a thirtieth of it, physics §20): the depths at the end are within each run's tolerance
// of a reference at the tightest the scene takes (0.1 nm, its own error within that). The
// tilted washer runs in (its rim wears fastest, then slower), so the rate changes by a
// hundred times over the life.
TEST(Life, TheDepthsConvergeWithTheirTolerance) {
  auto depth_at_end = [](const char* tolerance) {
    const StudyOutcome out =
        lived(life_scene(std::string("{type: life, duration: 500 h, report_every: 500 h, failure_load: false, "
                                     "tolerance: ") + tolerance + "}",
                         {"operating.load=150 N"}));
    return rows_of(out).back().rest.deepest;
  };
  const double reference = depth_at_end("0.1 nm");
  EXPECT_LT(std::abs(depth_at_end("10 nm") - reference), 10e-9 + 0.1e-9);
  EXPECT_LT(std::abs(depth_at_end("1 nm") - reference), 1e-9 + 0.1e-9);
}

// The failure load along the life (study.failure_load): each reported time has its
// search, distress.csv's row with its time, and the first is the new washer's: a search
// of the same bearing without the wear effect (the depths held at zero are its gap) finds
// it too, both located to the search's bracket width, 0.2 %.
TEST(Life, EachReportedTimeHasItsFailureLoadAndTheFirstIsTheNewWashers) {
  const StudyOutcome out =
      lived(life_scene("{type: life, duration: 200 h, report_every: 100 h}", {"operating.load=150 N"}));
  const std::vector<LifeRow>& rows = rows_of(out);
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(out.distress.size(), rows.size());
  EXPECT_EQ(out.parameter_columns, std::vector<std::string>{"t_h"});
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_TRUE(rows[k].failure_load) << k;
    EXPECT_EQ(out.distress[k].parameters, std::vector<double>{rows[k].time / 3600.0});
    EXPECT_EQ(out.distress[k].failure_load, rows[k].failure_load);
  }
  BearingModel unworn(load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                                 {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "operating.load=150 N"}));
  const DistressSearchSettings search = life_failure_search(150.0);
  const DistressSearch found = search_distress(unworn, search, {});
  ASSERT_TRUE(found.row.failure_load);
  EXPECT_NEAR(*rows.front().failure_load, *found.row.failure_load, 0.002 * *found.row.failure_load);
}

// Archard's worn volume is the contact's friction work times k (physics §20): each face's
// worn volume at the end of the life equals the integral over the life of the volume rate
// its states report, k·∫P_c dt, P_c the contact's friction power. The flat washer in
// contact of the test above, wearing a hundred times slower, so that its friction power
// moves from uniform pressure to uniform wear (by 4 %) over about an hour (the paper's
// washer runs in within minutes, faster than reported times can follow). The integral by
// the trapezoid rule over the reported times, every quarter and every half hour,
// extrapolated (Richardson, the rule's error O(Δt²) removed): the extrapolation errs by
// far less than the finer rule's own error estimate, |T_¼ − T_½|/3, which bounds it here;
// IDA's error in the volume adds, at most the depths' tolerance (their error at the end:
// TheDepthsConvergeWithTheirTolerance) over the whole film's area.
TEST(Life, EachFacesWornVolumeIsTheIntegralOfItsContactsFrictionPower) {
  const Scene s = life_scene("{type: life, duration: 10 h, tolerance: 0.1 nm, report_every: 0.25 h, failure_load: false}",
                             {"effects=[asperity_contact, wear]", "geometry.gear.tilt=0 mrad",
                              "friction={law: constant, coefficient: 0.1}",
                              "lubricant.viscosity={model: constant, value: 1e-6 Pa s}", "operating.load=300 N",
                              "surfaces.carrier.wear_rate=1e-17 m^3/(N m)", "surfaces.washer.wear_rate=2e-17 m^3/(N m)",
                              "limits.wear_depth=0.5 mm"});
  const double ida_error = 0.1e-9 * std::numbers::pi *
                           (s.washer.outer_radius * s.washer.outer_radius - s.washer.inner_radius * s.washer.inner_radius);
  const StudyOutcome out = lived(s);
  const std::vector<LifeRow>& rows = rows_of(out);
  ASSERT_EQ(rows.size(), 41u);
  ASSERT_EQ(out.states.size(), rows.size());
  EXPECT_EQ(rows.back().event, "end");
  for (const char* face : {"rest", "turn"}) {
    const std::string column = std::string("wear_volume_rate_") + face + "_mm3_h";
    std::vector<double> rate;  // m³/h
    for (const SolvedState& s : out.states) rate.push_back(1e-9 * s.state.reported_value(column).value_or(NAN));
    auto trapezoid = [&](std::size_t stride) {
      double sum = 0.0;
      for (std::size_t k = 0; k + stride < rate.size(); k += stride)
        sum += 0.5 * (rate[k] + rate[k + stride]) * (rows[k + stride].time - rows[k].time) / 3600.0;
      return sum;
    };
    const double fine = trapezoid(1), coarse = trapezoid(2), extrapolated = (4.0 * fine - coarse) / 3.0;
    const double volume = std::string(face) == "rest" ? rows.back().rest.volume : rows.back().turn.volume;
    ASSERT_GT(volume, 0.0);
    EXPECT_NEAR(extrapolated, volume, std::abs(fine - coarse) / 3.0 + ida_error) << face;
    EXPECT_LT(std::abs(fine - coarse), 0.01 * volume) << face;  // the rule resolves the life
  }
}

// A failure criterion passed at the operating point between two of IDA's steps ends the
// life there (its failure load has come down to the operating load), located on IDA's
// interpolant's depths, the bearing solved at each: the oil's peak temperature is then
// the limit to what a millionth of a step moves it (a step of hours at a few thousandths
// of a kelvin an hour: 1e-8 K; Newton's tolerance adds less), and within it at every
// earlier row. The flat
// washer in contact with its heat: its oil peak first cools as it wears from uniform
// pressure, then warms by a few hundredths of a kelvin as it wears on, so the life
// continues from the washer worn an hour (its coolest) under a flash point between.
TEST(Life, EndsWhereTheOperatingPointPassesAFailureCriterion) {
  const std::vector<std::string> flat{"effects=[asperity_contact, thermal, wear]", "geometry.gear.tilt=0 mrad",
                                      "friction={law: constant, coefficient: 0.1}",
                                      "lubricant.viscosity={model: constant, value: 1e-6 Pa s}", "operating.load=300 N",
                                      "surfaces.carrier.wear_rate=1e-17 m^3/(N m)",
                                      "surfaces.washer.wear_rate=1e-17 m^3/(N m)", "limits.wear_depth=0.5 mm"};
  const StudyOutcome hour =
      lived(life_scene("{type: life, duration: 1 h, tolerance: 0.1 nm, failure_load: false}", flat));
  std::vector<std::string> hot = flat;
  const double coolest = *out_state_value(hour.states.back(), "T_oil_peak_C");
  const double flash = coolest + 0.02;  // °C: reached a few hours on
  hot.push_back(fmt::format("lubricant.flash_temperature={} degC", flash));
  Scene s = life_scene("{type: life, duration: 20 h, report_every: 1 h, tolerance: 0.1 nm, failure_load: false}", hot);
  set_worn_washer(s, std::get<LifeOutcome>(hour.own).worn.back(), "the test");
  const StudyOutcome out = lived(s);
  const std::vector<LifeRow>& rows = rows_of(out);
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows.back().event, "failure");
  EXPECT_LT(rows.back().time, 20 * 3600.0);
  EXPECT_NEAR(*out_state_value(out.states.back(), "T_oil_peak_C"), flash, 1e-7);
  for (std::size_t k = 0; k + 1 < out.states.size(); ++k)
    EXPECT_LT(*out_state_value(out.states[k], "T_oil_peak_C"), flash) << k;
  EXPECT_NE(out.message.find("passes the oil_peak_temperature limit"), std::string::npos) << out.message;
}

// Distress in slow time is the fold come down to the operating load, not IDA's own
// trouble: a nearly parallel washer at 450 N wears into a shape that carries less (on
// 5x24 its failure load falls from 526 N), and where its life ends by distress the washer
// worn so far fails at the operating load. IDA meets convergence failures on the way
// (cavitation boundaries moving as the faces wear) that the bearing's steady state at
// the depths reached shows to be its own: it starts afresh there. The search of the worn
// washer brackets to 0.2 %; the fold moves on by what IDA's last step wore (measured far
// less), so 0.5 % bounds both.
TEST(Life, EndsByDistressWhereTheFoldHasComeDownToTheOperatingLoad) {
  const std::vector<std::string> scene{"geometry.gear.tilt=0.25 mrad", "operating.load=450 N"};
  const StudyOutcome out =
      lived(life_scene("{type: life, duration: 400 h, report_every: 400 h, failure_load: false}", scene));
  const LifeRow& end = rows_of(out).back();
  ASSERT_EQ(end.event, "distress");
  Scene worn = life_scene("{type: point}", scene);
  set_worn_washer(worn, std::get<LifeOutcome>(out.own).worn.back(), "the test");
  BearingModel model(worn);
  const DistressSearchSettings search = life_failure_search(450.0);
  const DistressSearch found = search_distress(model, search, {});
  ASSERT_TRUE(found.row.failure_load);
  EXPECT_NEAR(*found.row.failure_load, 450.0, 0.005 * 450.0);
}

// A washer already past a criterion where its life starts ends there, with its one row.
TEST(Life, AWasherPastACriterionAtItsStartEndsThere) {
  const StudyOutcome out = lived(life_scene("{type: life, duration: 100 h, failure_load: false}",
                                            {"operating.load=150 N", "lubricant.flash_temperature=30 degC"}));
  ASSERT_EQ(rows_of(out).size(), 1u);
  EXPECT_EQ(rows_of(out).front().event, "failure");
  EXPECT_EQ(rows_of(out).front().time, 0.0);
  EXPECT_NE(out.message.find("past the oil_peak_temperature limit already"), std::string::npos) << out.message;
}

// A life split in two (twb run --continue-from) ends where the whole does: the continued
// part starts from the depths the first ended with (read back exactly), the bearing
// solved there, and IDA afresh, where the whole life's IDA went on; each is within its
// tolerance (1 nm) of the true depths at the end, so they are within two of each other.
// The failure loads agree to the searches' bracket (0.2 %).
TEST(Life, AContinuedLifeEndsWhereTheWholeDoes) {
  const StudyOutcome whole = lived(life_scene("{type: life, duration: 200 h, report_every: 100 h, tolerance: 1 nm}",
                                              {"operating.load=150 N"}));
  const StudyOutcome first = lived(life_scene("{type: life, duration: 100 h, report_every: 100 h, tolerance: 1 nm}",
                                              {"operating.load=150 N"}));
  Scene rest = life_scene("{type: life, duration: 200 h, report_every: 100 h, tolerance: 1 nm}",
                          {"operating.load=150 N"});
  const std::vector<WornWasher>& worn = std::get<LifeOutcome>(first.own).worn;
  ASSERT_EQ(worn.size(), rows_of(first).size());
  set_worn_washer(rest, worn_washer_of(worn_washer_json(worn.back()), "the first part"), "the test");
  const StudyOutcome second = lived(rest);
  ASSERT_EQ(rows_of(second).size(), 2u);
  EXPECT_EQ(rows_of(second).front().time, 100 * 3600.0);
  const LifeRow &a = rows_of(whole).back(), &b = rows_of(second).back();
  EXPECT_EQ(b.time, a.time);
  EXPECT_EQ(b.event, "end");
  EXPECT_NEAR(b.rest.deepest, a.rest.deepest, 2e-9);
  EXPECT_NEAR(b.turn.deepest, a.turn.deepest, 2e-9);
  ASSERT_TRUE(a.failure_load && b.failure_load);
  EXPECT_NEAR(*b.failure_load, *a.failure_load, 0.002 * *a.failure_load);
  // The worn profile at every reported time, the last the washer the life ends with.
  EXPECT_EQ(std::get<LifeOutcome>(second.own).worn.back().time, b.time);
}

}  // namespace
}  // namespace twb
