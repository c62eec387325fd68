// A sensitivity study's derivatives (docs/physics.md section 16) against centred
// differences of whole solves, for every kind of input: a length, an angle, a body's
// conductivity, a roughness (new summit tables), a summit statistic, the oil's law, the
// speed, the ambient temperature and the load; and W_d's against the fold located again
// at p ± Δ. The paper's scene on the tests' 5 x 24 mesh.
//
// Tolerance, from the differences' own errors: a centred difference with step Δ is off
// the derivative by cΔ² (truncation), which the same difference at 2Δ measures,
// fd(2Δ) − fd(Δ) = 3cΔ²; the study's own step δ = Δ/10 leaves c·δ² = fd's truncation/100.
// The whole solves meet a residual of 1e-12, their quantities about 1e-10 relative,
// divided by the relative step 2·1e-3: 1e-7 of q/p. Allowed: 2|fd(2Δ) − fd(Δ)| +
// 1e-6·|q/p|, where a wrong sign, factor or missing term would be off by O(|dq/dp|).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "solver/fold_location.h"
#include "study/uncertainty/crossing_response.h"
#include "study/searches/distress_search.h"
#include "study/uncertainty/input_neighbours.h"
#include "twb/results/distress_table.h"
#include "study/uncertainty/sensitivity.h"
#include "study/searches/steady_solver.h"
#include "study/study_runner.h"
#include "study/study_support.h"
#include "twb/scene/scene_inputs.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

constexpr double kRelativeStep = 1e-3;  // Δ/|p| of the whole solves

Scene paper_scene(const std::string& study) {
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                    {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "solver.residual_tolerance=1e-12",
                     "operating.load=150 N", "study=" + study});
}

const std::vector<std::string> kStatePaths = {
    "geometry.washer.outer_diameter", "geometry.gear.tilt",    "materials.carrier.conductivity",
    "surfaces.washer.Rq",             "surfaces.asperities.eta_R_sigma", "lubricant.viscosity.G0",
    "operating.speed",                "operating.ambient",     "operating.load"};

std::string parameters(const std::vector<std::string>& paths) {
  std::string list;
  for (const std::string& p : paths) list += (list.empty() ? "" : ", ") + p;
  return "[" + list + "]";
}

// The state at the input set to `value`, solved from u.
BearingState solved_at(const Scene& scene, const std::string& path, double value, std::vector<double> u) {
  const std::pair<std::string, double> set[] = {{path, value}};
  BearingModel model(with_inputs(scene, set));
  SteadySolver solver(model, newton_settings(model.scene()));
  const SteadyReport rep = solver.solve(u);
  EXPECT_TRUE(rep.converged) << path << " = " << value << ": " << rep.message;
  return model.describe(u);
}

// The search the study runs, for its fold and crossings.
DistressSearch search_of(const Scene& scene, double load_end) {
  BearingModel base(scene);
  DistressSearchSettings settings;
  settings.load_start = 100.0;
  settings.load_end = load_end;
  settings.march_past_distress = false;
  return search_distress(base, settings, {});
}

const SensitivityRow* find_row(const StudyOutcome& out, const std::string& quantity, const std::string& path) {
  for (const SensitivityRow& r : std::get<SensitivityOutcome>(out.own).rows)
    if (r.quantity == quantity && r.parameter == path) return &r;
  return nullptr;
}

TEST(Sensitivity, StateDerivativesMatchWholeSolves) {
  const Scene scene = paper_scene("{type: sensitivity, parameters: " + parameters(kStatePaths) + "}");
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  ASSERT_EQ(out.states.size(), 1u);
  BearingModel base(scene);
  std::vector<double> u;
  ASSERT_TRUE(SteadySolver(base, newton_settings(scene)).solve_cold(u).converged);
  const std::vector<StateQuantity> at = state_quantities(base.describe(u));
  for (const std::string& path : kStatePaths) {
    const double p = scene_input(scene, path).value, delta = kRelativeStep * std::abs(p);
    std::vector<std::vector<StateQuantity>> q;  // p − 2Δ, p − Δ, p + Δ, p + 2Δ
    for (double k : {-2.0, -1.0, 1.0, 2.0}) q.push_back(state_quantities(solved_at(scene, path, p + k * delta, u)));
    for (std::size_t k = 0; k < at.size(); ++k) {
      const SensitivityRow* row = find_row(out, at[k].name, path);
      ASSERT_NE(row, nullptr) << at[k].name << " / " << path;
      const double fd1 = (q[2][k].value - q[1][k].value) / (2.0 * delta);
      const double fd2 = (q[3][k].value - q[0][k].value) / (4.0 * delta);
      const double tolerance = 2.0 * std::abs(fd2 - fd1) + 1e-6 * std::abs(at[k].value / p);
      EXPECT_NEAR(row->derivative, fd1, tolerance) << at[k].name << " / " << path << " (fd at 2Δ: " << fd2 << ")";
    }
  }
}

// The elasticity's input scale: an input's own value, but a temperature input's the
// washer's mean rise above the ambient (physics §16), since 350 K in kelvin would rank the
// ambient first by a derivative of a few newtons per kelvin. The torque's elasticities
// are the derivative times that scale over the torque, to rounding; and the summary says
// which scale its temperatures use.
TEST(Sensitivity, ATemperatureInputIsScaledByTheWashersRise) {
  const Scene scene = paper_scene("{type: sensitivity, parameters: [operating.ambient, geometry.gear.tilt]}");
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  const BearingState& at = out.states.back().state;
  const double rise = at.washer_mean_temperature - scene.operating.ambient;
  ASSERT_GT(rise, 0.0);
  const SensitivityRow* ambient = find_row(out, "torque_Nm", "operating.ambient");
  const SensitivityRow* tilt = find_row(out, "torque_Nm", "geometry.gear.tilt");
  ASSERT_TRUE(ambient && ambient->elasticity && tilt && tilt->elasticity);
  EXPECT_NEAR(*ambient->elasticity, ambient->derivative * rise / at.torque, 1e-12 * std::abs(*ambient->elasticity));
  EXPECT_NEAR(*tilt->elasticity, tilt->derivative * scene.gear.tilt / at.torque, 1e-12 * std::abs(*tilt->elasticity));
  const bool said = std::any_of(out.summary.begin(), out.summary.end(), [](const std::string& line) {
    return line.find("a temperature input's per the washer's rise above the ambient") != std::string::npos;
  });
  EXPECT_TRUE(said);
}

const std::vector<std::string> kFoldPaths = {"geometry.washer.outer_diameter", "geometry.gear.tilt",
                                             "surfaces.washer.Rq", "lubricant.viscosity.G0", "operating.speed",
                                             "operating.ambient"};

TEST(Sensitivity, FoldLoadDerivativesMatchTheFoldLocatedAgain) {
  const std::string study = "{type: sensitivity, load_start: 100 N, load_end: 400 N, parameters: " +
                            parameters(kFoldPaths) + "}";
  const Scene scene = paper_scene(study);
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  const DistressSearch found = search_of(scene, 400.0);
  ASSERT_TRUE(found.fold && found.fold_proven);
  const FoldPoint& fold = *found.fold;
  for (const std::string& path : kFoldPaths) {
    const double p = scene_input(scene, path).value, delta = kRelativeStep * std::abs(p);
    std::vector<double> w;  // W_d at p − 2Δ, p − Δ, p + Δ, p + 2Δ
    for (double k : {-2.0, -1.0, 1.0, 2.0}) {
      const std::pair<std::string, double> set[] = {{path, p + k * delta}};
      BearingModel m(with_inputs(scene, set));
      const FoldPoint again = locate_fold_near(m, fold.u, fold.lambda, fold.null_vector, newton_settings(m.scene()));
      ASSERT_FALSE(again.u.empty()) << path << ": " << again.message;
      w.push_back(again.lambda);
    }
    const SensitivityRow* row = find_row(out, "W_d_N", path);
    ASSERT_NE(row, nullptr) << path;
    const double fd1 = (w[2] - w[1]) / (2.0 * delta), fd2 = (w[3] - w[0]) / (4.0 * delta);
    const double tolerance = 2.0 * std::abs(fd2 - fd1) + 1e-6 * std::abs(fold.lambda / p);
    EXPECT_NEAR(row->derivative, fd1, tolerance) << path << " (fd at 2Δ: " << fd2 << ")";
  }
}

// The bronze washer at 3000 rpm fails by the flash temperature (configs/washers/
// bronze_cusn8.yaml): its crossing's derivatives against the crossing settled again at
// p ± Δ, for the limit itself, the speed, a conductivity, the tilt and the data sheet's
// viscosity at 40 degC (the Roelands fit follows it).
const std::vector<std::string> kCrossingPaths = {"lubricant.flash_temperature", "operating.speed",
                                                 "materials.washer.conductivity", "geometry.gear.tilt",
                                                 "lubricant.viscosity.kv40"};

TEST(Sensitivity, CrossingLoadDerivativesMatchTheCrossingSettledAgain) {
  const Scene scene = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_cusn8.yaml",
                                 {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24",
                                  "solver.residual_tolerance=1e-12",
                                  "study={type: sensitivity, load_start: 100 N, load_end: 1000 N, parameters: " +
                                      parameters(kCrossingPaths) + "}"});
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  const DistressSearch found = search_of(scene, 1000.0);
  BearingModel base(scene);
  const std::size_t flash = 1;  // kFailureCriteria's order
  ASSERT_EQ(kFailureCriteria[flash], LimitKind::oil_peak_temperature);
  ASSERT_GT(found.crossing_states.size(), flash);
  ASSERT_FALSE(found.crossing_states[flash].second.empty());
  std::string why;
  const std::optional<SettledCrossing> crossing = settle_crossing(
      base, LimitKind::oil_peak_temperature, found.crossing_states[flash].first, found.crossing_states[flash].second, why);
  ASSERT_TRUE(crossing) << why;
  for (const std::string& path : kCrossingPaths) {
    const double p = scene_input(scene, path).value, delta = kRelativeStep * std::abs(p);
    std::vector<double> w;  // the crossing at p − 2Δ, p − Δ, p + Δ, p + 2Δ
    for (double k : {-2.0, -1.0, 1.0, 2.0}) {
      const std::pair<std::string, double> set[] = {{path, p + k * delta}};
      BearingModel m(with_inputs(scene, set));
      const std::optional<SettledCrossing> again =
          settle_crossing(m, LimitKind::oil_peak_temperature, crossing->load, crossing->u, why);
      ASSERT_TRUE(again) << path << ": " << why;
      w.push_back(again->load);
    }
    const SensitivityRow* row = find_row(out, criterion_column(LimitKind::oil_peak_temperature), path);
    ASSERT_NE(row, nullptr) << path;
    const double fd1 = (w[2] - w[1]) / (2.0 * delta), fd2 = (w[3] - w[0]) / (4.0 * delta);
    const double tolerance = 2.0 * std::abs(fd2 - fd1) + 1e-6 * std::abs(crossing->load / p);
    EXPECT_NEAR(row->derivative, fd1, tolerance) << path << " (fd at 2Δ: " << fd2 << ")";
    // The flash point sets W_fail here: its rows are W_fail's.
    const SensitivityRow* fail = find_row(out, "W_fail_N", path);
    ASSERT_NE(fail, nullptr) << path;
    EXPECT_EQ(fail->derivative, row->derivative) << path;
  }
}

// Where a criterion's margin is nearly flat in load, Newton's step in load may reach a
// load the bearing cannot take: with the oil's flash temperature at the ambient, the
// oil's peak is past it at every load, by about as much at 100 N as at 10 N, and the
// first step from 100 N goes far below zero. Such a step went to the model as a negative
// load and ended a reliability study with the input error "load must be positive"; each
// now goes half the way to zero, and the root not found is reported, the model given
// back at its load.
TEST(Sensitivity, ACrossingWhoseMarginIsFlatIsNotSettledAtANegativeLoad) {
  Scene scene = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_cusn8.yaml",
                           {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24"});
  scene.lubricant.flash_temperature = scene.operating.ambient;
  BearingModel model(scene);
  const double scene_load = model.load();
  std::vector<double> u;
  {
    const ParameterScope at(model, 100.0);
    SteadySolver solver(model, newton_settings(scene));
    ASSERT_TRUE(solver.solve_cold(u).converged);
  }
  std::string why;
  std::optional<SettledCrossing> crossing;
  ASSERT_NO_THROW(crossing = settle_crossing(model, LimitKind::oil_peak_temperature, 100.0, u, why));
  EXPECT_FALSE(crossing) << "settled at " << crossing->load << " N";
  EXPECT_FALSE(why.empty()) << "a crossing not settled says why";
  EXPECT_EQ(model.load(), scene_load);
}

// An input at a bound of its range (a dry friction coefficient of zero, range >= 0): the
// one-sided fourth-order stencil, against the one-sided second-order difference of whole
// solves, (−3f(0) + 4f(Δ) − f(2Δ))/2Δ, whose truncation the same difference at 2Δ measures.
TEST(Sensitivity, AnInputAtItsBoundIsDifferencedOneSided) {
  const Scene scene = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                                 {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24",
                                  "solver.residual_tolerance=1e-12", "operating.load=175 N",
                                  "friction={law: constant, coefficient: 0}",
                                  "study={type: sensitivity, parameters: [friction.coefficient]}"});
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  const InputNeighbours n = input_neighbours(model, scene_input(scene, "friction.coefficient"));
  EXPECT_EQ(n.stencil.offsets, kForward.offsets);
  BearingModel base(scene);
  std::vector<double> u;
  ASSERT_TRUE(SteadySolver(base, newton_settings(scene)).solve_cold(u).converged);
  const double delta = 1e-3;
  std::vector<std::vector<StateQuantity>> q;  // at 0, Δ, 2Δ, 4Δ
  for (double k : {0.0, 1.0, 2.0, 4.0}) q.push_back(state_quantities(solved_at(scene, "friction.coefficient", k * delta, u)));
  const SensitivityRow* torque = find_row(out, "torque_Nm", "friction.coefficient");
  ASSERT_NE(torque, nullptr);
  const std::size_t k = 0;  // the torque: what dry friction moves first
  const double d1 = (-3 * q[0][k].value + 4 * q[1][k].value - q[2][k].value) / (2 * delta);
  const double d2 = (-3 * q[0][k].value + 4 * q[2][k].value - q[3][k].value) / (4 * delta);
  EXPECT_GT(std::abs(d1), 0.0);
  EXPECT_NEAR(torque->derivative, d1, 2 * std::abs(d2 - d1) + 1e-6 * std::abs(q[0][k].value)) << "(at 2Δ: " << d2 << ")";
}

TEST(Sensitivity, EveryWrittenInputByDefaultAndNoneTwice) {
  const Scene scene = paper_scene("{type: sensitivity}");
  ASSERT_FALSE(scene.inputs.empty());
  std::vector<std::string> paths;
  for (const SceneInput& in : scene.inputs) paths.push_back(in.path);
  std::sort(paths.begin(), paths.end());
  EXPECT_EQ(std::adjacent_find(paths.begin(), paths.end()), paths.end());
  for (const char* expected : {"geometry.gear.tilt", "surfaces.washer.Rq", "operating.speed", "operating.load",
                               "lubricant.viscosity.G0", "materials.washer.conductivity"})
    EXPECT_TRUE(std::binary_search(paths.begin(), paths.end(), expected)) << expected;
  // Nothing from the mesh, the solver or the study is an input.
  for (const std::string& p : paths) EXPECT_TRUE(is_bearing_input_path(p)) << p;
}

// The grooves' dam radius and width are placed on the grid (stepwise_input): a default
// study leaves them out, says so, and still differentiates the grooves' depth.
TEST(Sensitivity, InputsPlacedOnTheGridAreLeftOutAndNamed) {
  const Scene scene = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                                 {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "operating.load=150 N",
                                  "operating.sliding=washer_gear",
                                  "geometry.washer.grooves={count: 8, width: 2 mm, depth: 50 um, closed_at: 10 mm}",
                                  "study={type: sensitivity}"});
  EXPECT_FALSE(stepwise_input("geometry.washer.grooves.closed_at").empty());
  EXPECT_FALSE(stepwise_input("geometry.washer.grooves.land.taper.fraction").empty());
  EXPECT_TRUE(stepwise_input("geometry.washer.grooves.depth").empty());
  EXPECT_TRUE(stepwise_input("geometry.washer.grooves.land.step.depth").empty());
  EXPECT_TRUE(stepwise_input("geometry.gear.tilt").empty());
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {});
  ASSERT_FALSE(out.solver_failed) << out.message;
  EXPECT_EQ(find_row(out, "torque_Nm", "geometry.washer.grooves.closed_at"), nullptr);
  EXPECT_NE(find_row(out, "torque_Nm", "geometry.washer.grooves.depth"), nullptr);
  const bool named = std::any_of(out.summary.begin(), out.summary.end(), [](const std::string& line) {
    return line.find("left out, placed on the grid") != std::string::npos &&
           line.find("geometry.washer.grooves.closed_at") != std::string::npos;
  });
  EXPECT_TRUE(named);
}

TEST(Sensitivity, AnInputChangedIsTheSceneWrittenWithIt) {
  const Scene scene = paper_scene("{type: point}");
  const std::pair<std::string, double> set[] = {{"geometry.gear.tilt", 1.5e-3}};
  const Scene changed = with_inputs(scene, set);
  const Scene written = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                                   {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24",
                                    "solver.residual_tolerance=1e-12", "operating.load=150 N", "study={type: point}",
                                    "geometry.gear.tilt=1.5 mrad"});
  EXPECT_EQ(describe_scene(changed), describe_scene(written));
  // A default the file leaves out is an input too, at its resolved value.
  const SceneInput expansion = scene_input(scene, "materials.carrier.thermal_expansion");
  EXPECT_EQ(expansion.unit, "1/K");
  EXPECT_GT(expansion.value, 0.0);
  EXPECT_THROW(scene_input(scene, "mesh.radial_nodes"), std::invalid_argument);
  EXPECT_THROW(scene_input(scene, "geometry.gear.tilted"), std::invalid_argument);
}

}  // namespace
}  // namespace twb
