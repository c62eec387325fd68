// The reliability study on the bearing (docs/physics.md section 17): the paper's scene on
// the tests' 5 x 24 mesh with an uncertain ambient temperature. With one input W_fail
// falls monotonically in it, so the failure event is exactly {T_amb > T*} and FORM's
// P_f = Φ(−β) is exact: the Monte Carlo estimate must hold it within three of its
// standard errors (a 0.3 % chance to miss for a seed; the test is deterministic). The
// design points must lie on the failure surface: a failure search of its own at each
// design point's inputs finds the fold at the operating load (FORM: to its |g| ≤ 1e-4 W
// and the fold's Newton tolerance) or at the inverse FORM's load, also past the cusp
// where another criterion sets it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/bearing_model.h"
#include "study/searches/distress_search.h"
#include "study/uncertainty/failure_at_inputs.h"
#include "study/uncertainty/first_order_reliability.h"
#include "study/study_runner.h"
#include "twb/scene/scene_inputs.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

Scene paper_scene(const std::vector<std::string>& more) {
  std::vector<std::string> overrides{"mesh.radial_nodes=5", "mesh.circumferential_nodes=24"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml", overrides);
}

// The failure search at the scene's inputs with the ambient at `ambient`.
DistressRow failure_at(const Scene& scene, double ambient) {
  const std::pair<std::string, double> set[] = {{"operating.ambient", ambient}};
  BearingModel model(with_inputs(scene, set));
  DistressSearchSettings settings;
  settings.load_start = 50.0;
  settings.load_end = 400.0;
  settings.march_past_distress = false;
  return search_distress(model, settings, {}).row;
}

// Its fold's load: where W_fail is thermo-viscous distress, located to Newton's tolerance.
double fold_load_at(const Scene& scene, double ambient) {
  const DistressRow row = failure_at(scene, ambient);
  EXPECT_TRUE(row.fold_load.has_value()) << row.method;
  return row.fold_load.value_or(0.0);
}

// Its failure load settled to Newton's tolerance, whichever failure sets it (the fold,
// or a criterion's crossing just below it): a failure search at the ambient, each failure
// then settled (FailureLoadAtInputs::at, with nothing to follow from).
double settled_failure_load_at(const Scene& scene, double ambient) {
  DistressSearchSettings search;
  search.load_start = 50.0;
  search.load_end = 400.0;
  const FailureLoadAtInputs failure(scene, {"operating.ambient"}, {3.0}, search, 1);
  std::string why;
  const std::optional<FailureAtInputs> at = failure.at(std::vector<double>{ambient}, false, why);
  EXPECT_TRUE(at.has_value()) << why;
  return at ? at->load : 0.0;
}

// A sample's question, whether the bearing fails at a load, answered by a failure search
// that ends just above that load (no point settled yet to follow from) and by a move from
// the point the study's search settled: both as the full search's W_fail says, a percent
// either side of it (five times the bracket width the loads are located to).
TEST(ReliabilityStudy, ASampleFailsWhereItsFailureLoadLiesBelowTheLoad) {
  const Scene scene = paper_scene({"operating.load=150 N"});
  DistressSearchSettings search;
  search.load_start = 50.0;
  search.load_end = 400.0;
  for (const bool settled_first : {false, true}) {
    FailureLoadAtInputs failure(scene, {"operating.ambient"}, {3.0}, search, 1);
    std::string why;
    if (settled_first) {
      ASSERT_NE(failure.search_at(std::vector<double>{297.15}, {}, why), nullptr) << why;
    }
    for (const double ambient : {297.15, 303.15}) {
      const DistressRow row = failure_at(scene, ambient);
      ASSERT_TRUE(row.failure_load.has_value()) << row.method;
      const double w = *row.failure_load;
      const std::vector<double> x{ambient};
      const long searches = failure.searches();
      EXPECT_EQ(failure.fails_at(x, 0.99 * w, why), std::optional<bool>(false)) << ambient << " K: " << why;
      EXPECT_EQ(failure.fails_at(x, 1.01 * w, why), std::optional<bool>(true)) << ambient << " K: " << why;
      if (!settled_first) {
        EXPECT_EQ(failure.searches(), searches + 2) << "each answered by a search of its own";
      }
    }
  }
}

// Samples told by their state at the load (FailureLoadAtInputs::operate_at,
// study/operating_states.h), ambients rising past the failure surface: each sample whose
// failure load lies more than the bracket width from the load is told as the failure
// search says, whichever side of FORM's plane it is said to lie on (in several inputs the
// plane misplaces samples near the surface). On its own side the safe ones are told by
// their states at the load (the branch the failure search ran on, moved there); those
// with a fold below the load (no state at the load, whether distress or the oil's peak
// just below the fold sets W_fail) by their failure load; past the cusp, where the oil's
// peak temperature sets W_fail, the first by its failure load and the next by its state,
// moved from the first one's crossing. Said to be safe, a failing sample is first
// walked at the load from the states held there, which must not tell it safe.
TEST(ReliabilityStudy, ASampleToldByItsStateAtTheLoadFailsAsItsFailureLoadSays) {
  const Scene scene = paper_scene({"operating.load=150 N"});
  DistressSearchSettings search;
  search.load_start = 50.0;
  search.load_end = 400.0;
  std::vector<std::pair<double, DistressRow>> rows;
  for (const double ambient : {291.15, 294.15, 297.15, 299.15, 301.15, 303.15, 305.15, 307.15, 309.15})
    rows.emplace_back(ambient, failure_at(scene, ambient));
  for (const bool own_side : {true, false}) {
    FailureLoadAtInputs failure(scene, {"operating.ambient"}, {3.0}, search, 1);
    std::string why;
    ASSERT_NE(failure.search_at(std::vector<double>{297.15}, {}, why), nullptr) << why;
    failure.operate_at(150.0, std::vector<double>{305.0});
    std::uint64_t number = 0;
    int past_cusp = 0, told_safe = 0;
    for (const auto& [ambient, row] : rows) {
      ASSERT_TRUE(row.failure_load.has_value()) << row.method;
      if (std::abs(*row.failure_load - 150.0) <= 0.002 * 150.0) continue;
      const bool expected = *row.failure_load <= 150.0;
      // Past a fold below the load the cool branch holds no state there, whichever
      // criterion sets W_fail (the oil's peak may be crossed just below the fold).
      const bool past_fold = row.distress_load && *row.distress_load <= 150.0;
      const long before = failure.judged_by_state();
      const std::optional<bool> verdict = failure.fails_at(std::vector<double>{ambient}, 150.0, why,
                                                           FailureLoadAtInputs::Sample{number++, own_side ? !expected : true});
      EXPECT_EQ(verdict, std::optional<bool>(expected))
          << ambient << " K, W_fail " << *row.failure_load << " N: " << why << (own_side ? "" : " (said safe)");
      const bool told = failure.judged_by_state() > before;
      if (!expected) {
        EXPECT_TRUE(told) << ambient << " K: a safe sample told by its state";
        told_safe += told;
      } else if (own_side && past_fold) {
        EXPECT_FALSE(told) << ambient << " K: no state at the load past the fold";
      } else if (own_side) {
        EXPECT_EQ(told, past_cusp++ > 0) << ambient << " K, past the cusp";
      }
      failure.hold_samples();
    }
    EXPECT_GE(told_safe, 3) << "safe samples";
    if (own_side) {
      EXPECT_EQ(past_cusp, 2) << "samples failing by the flash temperature";
    }
  }
}

// The search's branch has a state at the load itself (the load on its grid): Newton has
// nothing to do there, and the stability test of the held state must factor J itself.
TEST(ReliabilityStudy, AStateOfTheSearchAtTheLoadIsHeldAsItIs) {
  const Scene scene = paper_scene({"operating.load=150 N"});
  DistressSearchSettings search;
  search.load_start = 50.0;
  search.load_end = 400.0;
  search.grid = {150.0};
  FailureLoadAtInputs failure(scene, {"operating.ambient"}, {3.0}, search, 1);
  std::string why;
  const DistressSearch* found = failure.search_at(std::vector<double>{297.15}, {}, why);
  ASSERT_NE(found, nullptr) << why;
  bool on_grid = false;
  for (const SolvedState& s : found->states) on_grid = on_grid || s.state.load == 150.0;
  ASSERT_TRUE(on_grid) << "the search's branch has a state at 150 N";
  failure.operate_at(150.0, std::vector<double>{297.15});
  EXPECT_EQ(failure.fails_at(std::vector<double>{297.15}, 150.0, why, FailureLoadAtInputs::Sample{0, true}),
            std::optional<bool>(false))
      << why;
  EXPECT_EQ(failure.judged_by_state(), 1) << "told by the state held";
}

// The samples' states held between batches in sample order: the estimate and how each
// sample was told do not depend on the thread count.
TEST(ReliabilityStudy, SamplingIsTheSameOnOneAndTwoThreads) {
  const Scene scene = paper_scene({"operating.load=150 N",
                                   "study={type: reliability, load_start: 50 N, load_end: 400 N, inputs: "
                                   "{operating.ambient: {distribution: normal, sd: 3 K}, geometry.gear.tilt: "
                                   "{distribution: normal, sd: 0.2 mrad}}, monte_carlo: {cov: 0.01, max_samples: 100}}"});
  std::vector<StudyOutcome> runs;
  for (const int threads : {1, 2}) {
    BearingModel model(scene);
    runs.push_back(run_study(model, {}, RunOptions{.threads = threads}));
    ASSERT_EQ(std::get<ReliabilityOutcome>(runs.back().own).rows.size(), 2u)
        << (runs.back().summary.empty() ? "" : runs.back().summary.back());
  }
  const ReliabilityRow &one = std::get<ReliabilityOutcome>(runs[0].own).rows[1],
                       &two = std::get<ReliabilityOutcome>(runs[1].own).rows[1];
  EXPECT_EQ(one.samples, two.samples);
  EXPECT_EQ(one.failures, two.failures);
  EXPECT_EQ(one.probability, two.probability);
  EXPECT_EQ(runs[0].summary, runs[1].summary);  // the count told by their states among them
  bool told_by_state = false;
  for (const std::string& line : runs[0].summary)
    if (line.find("told by their state") != std::string::npos) told_by_state = line.find("; 0 told") == std::string::npos;
  EXPECT_TRUE(told_by_state) << "the states at the load told some samples";
}

TEST(ReliabilityStudy, DesignPointsLieOnTheFailureSurfaceAndSamplingAgrees) {
  const Scene scene = paper_scene({"operating.load=150 N",
                                   "study={type: reliability, load_start: 50 N, load_end: 400 N, inputs: "
                                   "{operating.ambient: {distribution: normal, sd: 3 K}}, probabilities: [1e-2, 1e-3], "
                                   "monte_carlo: {cov: 0.1, max_samples: 1000}}"});
  BearingModel model(scene);
  const StudyOutcome out = run_study(model, {}, RunOptions{.threads = 2});
  const ReliabilityOutcome& reliability = std::get<ReliabilityOutcome>(out.own);
  ASSERT_EQ(reliability.rows.size(), 4u) << (out.summary.empty() ? "" : out.summary.back());
  const ReliabilityRow& form = reliability.rows[0];
  const ReliabilityRow& mc = reliability.rows[1];
  const ReliabilityRow& inverse = reliability.rows[2];
  ASSERT_EQ(form.method, "form");
  ASSERT_EQ(mc.method, "monte_carlo");
  ASSERT_EQ(inverse.method, "inverse_form");
  EXPECT_TRUE(form.converged);
  EXPECT_TRUE(inverse.converged);
  ASSERT_EQ(reliability.design_points.size(), 3u);

  // FORM: the design point's ambient fails the bearing at 150 N, and β is its distance.
  const DesignPointRow& star = reliability.design_points[0];
  EXPECT_NEAR(fold_load_at(scene, star.design_value), 150.0, 1e-4 * 150.0 + 1e-6);
  EXPECT_NEAR(*form.beta, (star.design_value - scene.operating.ambient) / 3.0, 1e-9);
  EXPECT_NEAR(form.probability, failure_probability(*form.beta), 1e-15);
  EXPECT_DOUBLE_EQ(star.importance, 1.0);
  EXPECT_LT(star.derivative, 0.0);  // a warmer oil fails sooner

  // Importance sampling holds FORM's exact probability.
  EXPECT_TRUE(mc.converged);
  EXPECT_EQ(*mc.unresolved, 0);
  EXPECT_NEAR(mc.probability, form.probability, 3.0 * *mc.cov * mc.probability);

  // Inverse FORM: at the load it gives, the inputs a β of 2.33 away fail (there by the
  // oil's peak temperature, crossed just below the fold).
  const DesignPointRow& inverse_star = reliability.design_points[1];
  EXPECT_NEAR(inverse_star.u, reliability_index(1e-2), 1e-3 * reliability_index(1e-2));
  EXPECT_NEAR(settled_failure_load_at(scene, inverse_star.design_value), inverse.load, 1e-6 * inverse.load);
  EXPECT_LT(inverse.load, 150.0);

  // At 1e-3 the ambient, 9 K above its mean, lies past this mesh's cusp (near 305.8 K):
  // no thermo-viscous distress there, and the bearing fails by the oil's peak temperature,
  // which Newton cannot follow the fold to; the search at those inputs finds it, to its
  // bracket width (0.002).
  const ReliabilityRow& past_cusp = reliability.rows[3];
  const DesignPointRow& past_cusp_star = reliability.design_points[2];
  EXPECT_TRUE(past_cusp.converged);
  const DistressRow there = failure_at(scene, past_cusp_star.design_value);
  EXPECT_FALSE(there.distress_load.has_value()) << there.method;
  ASSERT_TRUE(there.failure_load.has_value());
  EXPECT_NEAR(*there.failure_load, past_cusp.load, 0.002 * past_cusp.load);
}

}  // namespace
}  // namespace twb
