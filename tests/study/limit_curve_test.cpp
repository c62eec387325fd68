// Limit curves beside the fold curve (study type distress_curve, study/limit_curve.h): on
// the bronze washer over 1000-6000 rpm (coarse mesh), every failure criterion's crossing
// continued in speed. Each point is where the cool branch, followed up from the light
// load at that speed, crosses the criterion (to the bracket width), and no point lies at
// or above the distress fold at its speed (that would be the hot branch).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "model/limit_thresholds.h"
#include "solver/natural_continuation.h"
#include "study/searches/steady_solver.h"
#include "study/study_runner.h"
#include "study/study_support.h"
#include "twb/results/distress_table.h"
#include "twb/results/fold_curve_table.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

Scene bronze_curve() {
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_cusn8.yaml",
                    {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24",
                     "study={type: distress_curve, parameter: speed, from: 1000 rpm, to: 6000 rpm, load_start: 100 N, "
                     "load_end: 2000 N, error_estimate: none}"});
}

struct Shared {
  BearingModel model{bronze_curve()};
  StudyOutcome out;
  Shared() { out = run_study(model, {}, RunOptions{}); }
};
Shared& shared() {
  static Shared s;
  return s;
}

// The rows of fold_curve.csv (a distress curve's study, so there).
const std::vector<FoldCurveRow>& curve_rows(const StudyOutcome& out) {
  return std::get<DistressCurveOutcome>(out.own).rows;
}

std::map<std::string, std::vector<const FoldCurveRow*>> limit_rows(const StudyOutcome& out) {
  std::map<std::string, std::vector<const FoldCurveRow*>> rows;
  for (const FoldCurveRow& r : curve_rows(out))
    for (LimitKind kind : kFailureCriteria)
      if (r.fold == FoldKind::limit && r.limit == kind) rows[fold_name(r)].push_back(&r);
  return rows;
}

TEST(LimitCurve, EveryCriterionCrossedAtTheLowEndIsContinued) {
  const auto rows = limit_rows(shared().out);
  // At 1000 rpm the flash point, the bronze's limit, the oil's maximum, the film ratio and
  // the scuffing temperature are all crossed below 2000 N (the distress search there says
  // so).
  ASSERT_FALSE(shared().out.distress.empty());
  const DistressRow& low_end = shared().out.distress.front();
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    const std::string name(limit_name(kFailureCriteria[c]));
    if (!low_end.criterion_loads[c]) continue;
    ASSERT_TRUE(rows.count(name)) << name;
    // Its first point is the search's crossing.
    EXPECT_EQ(rows.at(name).front()->state.load, *low_end.criterion_loads[c]) << name;
    EXPECT_GT(rows.at(name).size(), 5u) << name;
  }
  EXPECT_EQ(rows.size(), 5u);
}

// The curve's range was given in rpm: its summary lines say rpm, as the scene did (a
// curve from 1000 rpm to 6000 rpm said 104.72 to 628.319 rad/s, and ended "at 453.786").
TEST(LimitCurve, ASpeedCurveGivenInRpmIsSaidInRpm) {
  const StudyOutcome& out = shared().out;
  EXPECT_TRUE(out.speeds_in_rpm);
  int limit_lines = 0;
  for (const std::string& line : out.summary) {
    if (line.rfind("limit curve", 0) != 0) continue;
    ++limit_lines;
    EXPECT_NE(line.find(" at 1000 rpm"), std::string::npos) << line;
    EXPECT_EQ(line.find("rad/s"), std::string::npos) << line;
  }
  EXPECT_EQ(limit_lines, 5);
  EXPECT_EQ(summary_lines(out).front().rfind("distress at 1000 rpm: ", 0), 0u) << summary_lines(out).front();
}

TEST(LimitCurve, PointsAreCrossingsOfTheCoolBranch) {
  BearingModel model(bronze_curve());
  const OperatingLimits limits = OperatingLimits::of(model.scene());
  NaturalSettings natural;
  natural.newton = newton_settings(model.scene());
  for (const auto& [name, rows] : limit_rows(shared().out)) {
    LimitKind kind{};
    for (LimitKind k : kFailureCriteria)
      if (limit_name(k) == name) kind = k;
    // Two points of each curve: its middle and its end (its start is the search's own
    // crossing, checked in failure_load_test.cpp).
    for (const FoldCurveRow* r : {rows[rows.size() / 2], rows.back()}) {
      const double w = r->state.load;
      model.set_speed(r->parameter);
      model.set_load(100.0);
      std::vector<double> u;
      ASSERT_TRUE(SteadySolver(model, natural.newton).solve_cold(u).converged);
      // The cool branch from 100 N to 0.2 % below and above the crossing: the margin
      // changes sign between (the bracket width the curve locates to).
      natural.initial_step = natural.max_step = 0.05 * w;
      natural.min_step = 1e-6 * w;
      const NaturalReport below = continue_in_parameter(model, u, 100.0, 0.998 * w, natural);
      ASSERT_TRUE(below.reached_target) << name << " at " << r->parameter << ": " << below.message;
      model.set_load(0.998 * w);
      const double m_below =
          *failure_margin(kind, LimitValues::of(model.describe(u), true), limits);
      natural.initial_step = natural.max_step = 0.004 * w;
      const NaturalReport above = continue_in_parameter(model, u, 0.998 * w, 1.002 * w, natural);
      ASSERT_TRUE(above.reached_target) << name << " at " << r->parameter << ": " << above.message;
      model.set_load(1.002 * w);
      const double m_above = *failure_margin(kind, LimitValues::of(model.describe(u), true), limits);
      EXPECT_GT(m_below, 0.0) << name << " at " << r->parameter << " rad/s, " << w << " N";
      EXPECT_LE(m_above, 0.0) << name << " at " << r->parameter << " rad/s, " << w << " N";
    }
  }
}

TEST(LimitCurve, NoPointLiesAboveTheDistressFold) {
  const StudyOutcome& out = shared().out;
  std::vector<std::pair<double, double>> folds;
  for (const FoldCurveRow& r : curve_rows(out))
    if (r.fold == FoldKind::distress) folds.emplace_back(r.parameter, r.state.load);
  ASSERT_GE(folds.size(), 2u) << "the washer has a distress fold at the high speeds";
  std::sort(folds.begin(), folds.end());
  for (const auto& [name, rows] : limit_rows(out))
    for (const FoldCurveRow* r : rows) {
      if (r->parameter < folds.front().first || r->parameter > folds.back().first) continue;
      const auto hi = std::lower_bound(folds.begin(), folds.end(), std::pair{r->parameter, -1e300});
      const auto lo = hi == folds.begin() ? hi : hi - 1;
      const double w_d = hi == lo ? hi->second
                                  : lo->second + (hi->second - lo->second) * (r->parameter - lo->first) /
                                                     (hi->first - lo->first);
      EXPECT_LT(r->state.load, w_d) << name << " at " << r->parameter;
    }
}

// A crossing that falls steeply with the parameter: on the paper's bearing the scuffing
// crossing falls from about 880 N at 136 rad/s to 160 N at 370 rad/s (coarse mesh), and
// the parabola through the last three crossings once predicted a negative load, which
// ended the curve at its first point ("load must be positive"). Every criterion
// crossed at the low end is continued past its start.
TEST(LimitCurve, ACrossingThatFallsSteeplyIsFollowed) {
  BearingModel model(load_scene(std::string(TWB_SOURCE_DIR) + "/configs/studies/distress_curve.yaml",
                                {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "study.error_estimate=none"}));
  const StudyOutcome out = run_study(model, {}, RunOptions{});
  const auto rows = limit_rows(out);
  ASSERT_FALSE(out.distress.empty());
  const DistressRow& low_end = out.distress.front();
  ASSERT_TRUE(criterion_load(low_end, LimitKind::scuffing)) << "scuffing is crossed at 136 rad/s";
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    if (!low_end.criterion_loads[c]) continue;
    const std::string name(limit_name(kFailureCriteria[c]));
    ASSERT_TRUE(rows.count(name)) << name;
    EXPECT_GE(rows.at(name).size(), 3u) << name << " is followed past its start";
  }
}

// The curve's pieces (both ends' searches, the fold's error bars in chains that follow it, each
// limit curve) run on two threads as on one: the same files to the last bit.
TEST(LimitCurve, TheSameCurvesOnOneThreadAndOnTwo) {
  Scene scene = bronze_curve();
  // One refinement: the chains and jobs are the same either way.
  std::get<DistressCurveSettings>(scene.study.settings).error_bars = {.estimate = ErrorEstimate::richardson,
                                                                       .tolerance = 0.0};
  BearingModel one(scene), two(scene);
  const StudyOutcome serial = run_study(one, {}, RunOptions{.threads = 1});
  const StudyOutcome parallel = run_study(two, {}, RunOptions{.threads = 2});
  const DistressCurveOutcome &serial_curve = std::get<DistressCurveOutcome>(serial.own),
                             &parallel_curve = std::get<DistressCurveOutcome>(parallel.own);
  ASSERT_TRUE(std::any_of(serial_curve.rows.begin(), serial_curve.rows.end(),
                          [](const FoldCurveRow& r) { return r.fine_load.has_value(); }))
      << "the fold's error bars are computed";
  EXPECT_EQ(limit_rows(serial).size(), 5u);
  EXPECT_EQ(fold_curve_csv(parallel_curve.rows, parallel_curve.column, ""),
            fold_curve_csv(serial_curve.rows, serial_curve.column, ""));
  EXPECT_EQ(distress_csv(parallel.distress, parallel.parameter_columns),
            distress_csv(serial.distress, serial.parameter_columns));
  EXPECT_EQ(parallel.summary, serial.summary);
}

}  // namespace
}  // namespace twb
