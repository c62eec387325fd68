// The fold curve W_d(ω) of the paper's bearing (study type distress_curve; solver/
// fold_curve.h) on the coarse mesh: it passes through the W_d a distress search brackets
// at four speeds, and its cusp lies between the speeds where a direct search does and
// does not find a fold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/table1_scene.h"
#include "solver/fold_curve.h"
#include "study/searches/distress_search.h"
#include "study/accuracy/richardson.h"
#include "study/study_runner.h"

namespace twb {
namespace {

struct Speed final : SecondParameter {
  explicit Speed(BearingModel& m) : model(m) {}
  double value() const override { return model.speed(); }
  void set(double w) override { model.set_speed(w); }
  BearingModel& model;
};

Scene coarse_scene() {
  Scene s = testing::table1_scene(true, true, true, true, 2000.0, 100.0);
  testing::use_coarse_mesh(s);
  return s;
}

// The study of the curve traced above: W_d(ω) from 2000 down to 136 rad/s.
Scene speed_curve_scene() {
  Scene scene = coarse_scene();
  DistressCurveSettings curve;
  curve.curve_parameter = CurveParameter::speed;
  curve.from = 2000.0;
  curve.to = 136.0;
  curve.search.loads = {100.0, 1000.0};
  // No error bars: the tests of the bars (the single refinement's, and a tolerance's
  // sequence, six times the cost and more for each further mesh) ask for them.
  curve.error_bars.estimate = ErrorEstimate::none;
  scene.study.settings = curve;
  return scene;
}

// The curve's settings (the scene's study is one).
DistressCurveSettings& curve_of(Scene& scene) { return std::get<DistressCurveSettings>(scene.study.settings); }

DistressSearchSettings search_range() {
  DistressSearchSettings s;
  s.load_start = 100.0;
  s.load_end = 1000.0;
  s.march_past_distress = false;
  return s;
}

struct SharedCurve {
  BearingModel model{coarse_scene()};
  DistressSearch start;
  FoldCurve curve;
  SharedCurve() {
    model.set_speed(2000.0);
    start = search_distress(model, search_range(), {});
    if (!start.fold) return;
    Speed speed(model);
    FoldCurveSettings fs;
    fs.p_min = 136.0;
    fs.p_max = 2000.0;
    fs.direction = -1;
    fs.arclength.newton.max_iterations = 12;
    fs.arclength.initial_step = 0.02;
    fs.arclength.max_step = 0.2;
    fs.arclength.max_points = 400;
    curve = trace_fold_curve(model, speed, *start.fold, fs);
  }
};
SharedCurve& shared() {
  static SharedCurve s;
  return s;
}

// Where the curve has a distress fold at ω, the same as a whole distress search at ω
// finds and proves by transients: the bracket's W_d is the fold, so they agree to the
// solvers' tolerances; 0.2 % is the bound.
TEST(DistressCurve, PassesThroughTheSearchedDistressLoads) {
  SharedCurve& s = shared();
  ASSERT_TRUE(s.start.fold) << s.start.row.method;
  ASSERT_GT(s.curve.points.size(), 5u) << s.curve.message;
  Speed speed(s.model);
  for (const double w : {545.0, 953.0, 1367.0, 1800.0}) {
    SCOPED_TRACE(w);
    // The nearest point on the distress side of the curve.
    const FoldCurvePoint* near = nullptr;
    for (const FoldCurvePoint& p : s.curve.points)
      if (p.curvature > 0 && (!near || std::abs(p.p - w) < std::abs(near->p - w))) near = &p;
    ASSERT_NE(near, nullptr);
    const auto on_curve = fold_at(s.model, speed, *s.start.fold, *near, w, NewtonSettings{.max_iterations = 12});
    ASSERT_TRUE(on_curve);
    BearingModel fresh(coarse_scene());
    fresh.set_speed(w);
    const DistressSearch found = search_distress(fresh, search_range(), {});
    ASSERT_TRUE(found.row.distress_load && found.row.bracket_low && found.row.bracket_high) << found.row.method;
    EXPECT_NEAR(on_curve->lambda, *found.row.distress_load, 0.002 * *found.row.distress_load);
    EXPECT_GT(on_curve->lambda, *found.row.bracket_low);
    EXPECT_LT(on_curve->lambda, *found.row.bracket_high);
  }
}

// The curve turns back in ω once, at a cusp: the fold's curvature changes sign (distress
// becomes the hot branch's recovery). A direct search 3 % above the cusp speed finds a
// fold, 3 % below it finds none (gradual heating); so does the whole distress search
// below it, where the slowest mode slows without a fold (it once bisected a runaway
// there that the transients of every state never saw).
TEST(DistressCurve, CuspBetweenFoldAndNoFold) {
  SharedCurve& s = shared();
  ASSERT_EQ(s.curve.turns.size(), 1u) << s.curve.message;
  const CurveTurn& cusp = s.curve.turns.front();
  EXPECT_TRUE(cusp.cusp);
  EXPECT_GT(cusp.p, 136.0);
  EXPECT_LT(cusp.p, 2000.0);
  for (const auto& [factor, fold_expected] : {std::pair{1.03, true}, std::pair{0.97, false}}) {
    BearingModel fresh(coarse_scene());
    fresh.set_speed(factor * cusp.p);
    DistressSearchSettings settings = search_range();
    settings.fold_only = true;
    const DistressSearch found = search_distress(fresh, settings, {});
    EXPECT_EQ(found.row.fold_load.has_value(), fold_expected)
        << factor << " x cusp speed " << cusp.p << ": " << found.row.method;
  }
  BearingModel below(coarse_scene());
  below.set_speed(0.97 * cusp.p);
  const DistressSearch gradual = search_distress(below, search_range(), {});
  EXPECT_FALSE(gradual.row.distress_load) << gradual.row.method;
  EXPECT_EQ(gradual.row.verdict, DistressVerdict::gradual_heating) << gradual.row.method;
}

// The study writes the same curve: its rows run from the start's distress fold through
// the cusp to recovery folds, and the cusp row is the solver's; the limit curves' rows
// (a failure criterion's name in the fold column) follow the fold curve's.
TEST(DistressCurve, StudyWritesTheCurveAndTheCusp) {
  Scene scene = speed_curve_scene();
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  const DistressCurveOutcome& curve = std::get<DistressCurveOutcome>(out.own);
  ASSERT_FALSE(curve.rows.empty());
  EXPECT_EQ(curve.column, "speed_rad_s");
  EXPECT_EQ(curve.rows.front().fold, FoldKind::distress);
  const auto limit = [](const FoldCurveRow& r) {
    return r.fold == FoldKind::limit;
  };
  const auto first_limit = std::find_if(curve.rows.begin(), curve.rows.end(), limit);
  EXPECT_TRUE(std::all_of(first_limit, curve.rows.end(), limit));
  ASSERT_NE(first_limit, curve.rows.begin());
  EXPECT_EQ((first_limit - 1)->fold, FoldKind::recovery);
  const auto cusp = std::find_if(curve.rows.begin(), curve.rows.end(), [](const FoldCurveRow& r) { return r.fold == FoldKind::cusp; });
  ASSERT_NE(cusp, curve.rows.end());
  ASSERT_EQ(shared().curve.turns.size(), 1u);
  EXPECT_NEAR(cusp->parameter, shared().curve.turns.front().p, 1e-6 * cusp->parameter);
  ASSERT_FALSE(out.summary.empty());
  EXPECT_NE(out.summary.front().find("cusp"), std::string::npos) << out.summary.front();
}

// W_d's error bar all along the curve (study.error_estimate: richardson, the default):
// every distress fold has its fold on the mesh refined by two, and the first is the one
// the refined mesh's own search finds at that speed (both Newton on the same fold
// system to the scaled residual 1e-10: 1e-8 relative leaves room for its conditioning,
// as in richardson_test.cpp). Without the estimate the columns stay empty.
TEST(DistressCurve, EveryFoldOfTheCurveHasItsErrorBar) {
  Scene scene = speed_curve_scene();
  // The single refinement's bar, of the formal order.
  curve_of(scene).error_bars = {.estimate = ErrorEstimate::richardson, .tolerance = 0.0};
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  const DistressCurveOutcome& curve = std::get<DistressCurveOutcome>(out.own);
  ASSERT_FALSE(curve.rows.empty());
  long distress = 0, recovery_with_bar = 0;
  for (const FoldCurveRow& r : curve.rows) {
    if (r.fold == FoldKind::distress) {
      ++distress;
      ASSERT_TRUE(r.fine_load && r.extrapolated_load && r.discretization_error) << "at " << r.parameter;
      // Finer meshes carry more load here (W_d 7 % low on 9×66, 20 % on 5×24).
      EXPECT_GT(*r.fine_load, r.state.load);
      EXPECT_NEAR(*r.extrapolated_load, *r.fine_load + (*r.fine_load - r.state.load) / 3.0, 1e-12 * *r.fine_load);
    }
    if (r.fold == FoldKind::cusp || r.fold == FoldKind::turn) {
      EXPECT_FALSE(r.fine_load);
    }
    if (r.fold == FoldKind::recovery && r.fine_load) ++recovery_with_bar;
  }
  EXPECT_GT(distress, 3);
  EXPECT_GT(recovery_with_bar, 0);

  const FoldCurveRow& first = curve.rows.front();
  Scene fine = refined_mesh(scene);
  fine.operating.speed = first.parameter;
  BearingModel refined(fine);
  DistressSearchSettings s;
  s.load_start = curve_of(scene).search.loads.start;
  s.load_end = curve_of(scene).search.loads.end;
  s.fold_only = true;
  const DistressSearch own = search_distress(refined, s, {});
  ASSERT_TRUE(own.row.fold_load && own.fold) << own.row.method;
  ASSERT_EQ(own.fold->method, FoldMethod::minimally_augmented);  // the tolerance's argument
  EXPECT_NEAR(*first.fine_load, *own.row.fold_load, 1e-8 * *own.row.fold_load);

  curve_of(scene).error_bars.estimate = ErrorEstimate::none;
  BearingModel plain(scene);
  const StudyOutcome without = run_study(plain, {});
  const std::vector<FoldCurveRow>& plain_rows = std::get<DistressCurveOutcome>(without.own).rows;
  EXPECT_TRUE(std::none_of(plain_rows.begin(), plain_rows.end(),
                           [](const FoldCurveRow& r) { return r.fine_load.has_value(); }));
}

// A curve to a tolerance (study.tolerance): every fold and every limit curve's crossing
// on the mesh sequence. On the coarse test mesh (5 x 24, W_d 20 % low) no two-mesh bar
// meets 1 %, so each distress fold is located on three meshes (the two allowed
// refinements), with an order, and its tolerance flag says whether its bar is within 1 %.
// Its start is the same fold the end's search finds and refines on its own (the
// controller's cover of a finer sequence is richardson_test.cpp's): each refined fold is
// located to a thousandth of its coarse-to-fine step (about 0.03 N here), which moves the
// estimate by well under 0.1 % of W_d. The limit curve's first point is the search's own
// crossing, refined from the same state by the same sequence: the same bar to the bit.
TEST(DistressCurve, ACurveToAToleranceGoesAlongTheMeshSequenceAtEveryPoint) {
  Scene scene = speed_curve_scene();
  curve_of(scene).to = 1900.0;
  curve_of(scene).error_bars = {.estimate = ErrorEstimate::richardson, .tolerance = 0.01};
  scene.mesh.max_refinements = 2;
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  const DistressCurveOutcome& curve = std::get<DistressCurveOutcome>(out.own);
  ASSERT_FALSE(out.distress.empty());
  const DistressRow& end = out.distress.front();
  ASSERT_EQ(end.speed, 2000.0);
  ASSERT_TRUE(end.extrapolated_load && end.discretization_error) << end.method;
  EXPECT_EQ(end.fold_convergence.meshes, "5x24 9x48 17x96");
  long distress = 0, limits = 0;
  for (const FoldCurveRow& r : curve.rows) {
    if (r.fold == FoldKind::distress) {
      ++distress;
      ASSERT_TRUE(r.extrapolated_load && r.discretization_error) << "at " << r.parameter;
      EXPECT_EQ(r.convergence.meshes, "5x24 9x48 17x96") << "at " << r.parameter;
      EXPECT_TRUE(r.convergence.order.has_value()) << "at " << r.parameter;
      if (distress == 1) {
        EXPECT_EQ(r.parameter, 2000.0);
        EXPECT_NEAR(*r.extrapolated_load, *end.extrapolated_load, 1e-3 * *end.extrapolated_load);
        EXPECT_NEAR(*r.discretization_error, *end.discretization_error, 1e-3 * *end.extrapolated_load);
      }
    }
    if (!r.extrapolated_load) continue;
    ASSERT_TRUE(r.convergence.tolerance_met.has_value()) << fold_name(r) << " at " << r.parameter;
    EXPECT_EQ(*r.convergence.tolerance_met, *r.discretization_error <= 0.01 * std::abs(*r.extrapolated_load))
        << fold_name(r) << " at " << r.parameter;
    if (r.fold == FoldKind::limit && r.limit == LimitKind::scuffing && limits++ == 0) {
      EXPECT_EQ(r.parameter, 2000.0);
      EXPECT_EQ(r.extrapolated_load, end.criterion_extrapolated[*criterion_index(LimitKind::scuffing)]);
      EXPECT_EQ(r.convergence.meshes, "5x24 9x48 17x96");
    }
  }
  EXPECT_GE(distress, 2);
  EXPECT_GE(limits, 2) << "scuffing is crossed below W_d along the curve";
  // No bar of the coarse test mesh reaches 1 %: the summary warns, as a search's does.
  EXPECT_TRUE(std::any_of(out.summary.begin(), out.summary.end(), [](const std::string& line) {
    return line.starts_with("warning: fold curve: not within the tolerance");
  }));
}

// A family of curves, one per dry friction coefficient (the constant law, Fig. 15): each
// has its cusp, and more friction heats the contact more, so the cusp moves to lower
// speeds (at 545 rad/s the paper's f = 0.1 has no fold while 0.2 has one).
TEST(DistressCurve, FamilyOfCurvesByFrictionCoefficient) {
  Scene scene = speed_curve_scene();
  scene.friction.law = FrictionLaw::constant;
  curve_of(scene).axes = {MapAxis{.parameter = MapParameter::friction_coefficient, .path = {}, .unit = {}, .values = {0.1, 0.3}}};
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  const DistressCurveOutcome& curve = std::get<DistressCurveOutcome>(out.own);
  EXPECT_EQ(out.parameter_columns, std::vector<std::string>{"friction_coefficient"});
  std::vector<double> cusps;
  for (const double f : {0.1, 0.3}) {
    const auto cusp = std::find_if(curve.rows.begin(), curve.rows.end(),
                                   [&](const FoldCurveRow& r) { return r.fold == FoldKind::cusp && r.member == f; });
    ASSERT_NE(cusp, curve.rows.end()) << "f = " << f;
    cusps.push_back(cusp->parameter);
  }
  EXPECT_GT(cusps[0], cusps[1]);
  EXPECT_EQ(std::count_if(curve.rows.begin(), curve.rows.end(), [](const FoldCurveRow& r) { return !r.member; }),
            0);
  // The members on two threads: the same curves, row for row, to the last bit.
  BearingModel again(scene);
  const StudyOutcome parallel = run_study(again, {}, RunOptions{.threads = 2});
  const DistressCurveOutcome& parallel_curve = std::get<DistressCurveOutcome>(parallel.own);
  EXPECT_EQ(fold_curve_csv(parallel_curve.rows, parallel_curve.column, parallel.parameter_columns.front()),
            fold_curve_csv(curve.rows, curve.column, out.parameter_columns.front()));
  EXPECT_EQ(distress_csv(parallel.distress, parallel.parameter_columns), distress_csv(out.distress, out.parameter_columns));
}

}  // namespace
}  // namespace twb
