// A followed distress map (study.method: follow, study/followed_map.h): each combination's
// failure load settled by Newton from its neighbour's, against a failure search at every
// combination, and independent of the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "study/study_runner.h"
#include "twb/results/distress_table.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

// The paper's bearing on the tests' 5 × 24 mesh, with the constant friction law, over
// speed × friction coefficient × gear tilt near its folds at 545 rad/s.
StudyOutcome grid(const std::string& method, int threads) {
  BearingModel model(load_scene(
      std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
      {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "friction={law: constant, coefficient: 0.2}",
       "study={type: distress_map, method: " + method +
           ", speeds: [500 rad/s, 550 rad/s, 600 rad/s], load_start: 60 N, load_end: 2000 N, error_estimate: none, "
           "parameter: [{name: friction_coefficient, values: [0.18, 0.2, 0.22]}, {name: geometry.gear.tilt, "
           "values: [0.9 mrad, 1.1 mrad]}]}"}));
  return run_study(model, {}, RunOptions{.threads = threads});
}

// Every row's fold and failure load are the searches': both solve the minimally augmented
// fold system (or the margin's root) to the solver's residual tolerance, 1e-10 of the
// scaled residual, which moves a fold's load by far less than 1e-8 of itself; the test
// allows 1e-8. The first combination is searched, and most of the rest followed.
TEST(FollowedMap, EachRowIsTheSearchesFailureLoad) {
  const StudyOutcome searched = grid("search", 2), followed = grid("follow", 2);
  ASSERT_EQ(followed.distress.size(), 18u);
  ASSERT_EQ(searched.distress.size(), 18u);
  EXPECT_EQ(followed.parameter_columns, searched.parameter_columns);
  int by_newton = 0;
  for (std::size_t k = 0; k < 18; ++k) {
    const DistressRow &f = followed.distress[k], &s = searched.distress[k];
    SCOPED_TRACE(std::to_string(k) + ": " + f.method);
    EXPECT_EQ(f.speed, s.speed);
    EXPECT_EQ(f.parameters, s.parameters);
    ASSERT_EQ(f.failure_load.has_value(), s.failure_load.has_value());
    if (s.failure_load) {
      EXPECT_NEAR(*f.failure_load, *s.failure_load, 1e-8 * *s.failure_load);
    }
    ASSERT_EQ(f.criterion.has_value(), s.criterion.has_value());
    if (s.criterion) {
      EXPECT_EQ(criterion_name(*f.criterion), criterion_name(*s.criterion));
    }
    ASSERT_EQ(f.fold_load.has_value(), s.fold_load.has_value());
    if (s.fold_load) {
      EXPECT_NEAR(*f.fold_load, *s.fold_load, 1e-8 * *s.fold_load);
    }
    by_newton += f.method.starts_with("followed by Newton");
  }
  EXPECT_TRUE(followed.distress.front().method.starts_with("searched")) << followed.distress.front().method;
  EXPECT_GE(by_newton, 12);
}

// A washer that fails by a limit first: the bronze washer, whose film's flash temperature
// passes the oil's flash point before any fold. The followed crossing is the margin's
// root to the solver's tolerance; the search's is its secant's, stopped within a tenth
// of the bracket width (2e-4 of the load): the rows agree to that.
TEST(FollowedMap, ALimitsCrossingIsFollowedToo) {
  auto bronze = [](const std::string& method) {
    BearingModel model(load_scene(
        std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_cusn8.yaml",
        {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24",
         "study={type: distress_map, method: " + method +
             ", speeds: [3000 rpm, 3300 rpm], load_start: 100 N, load_end: 4000 N, error_estimate: none, "
             "parameter: {name: geometry.gear.tilt, values: [0.9 mrad, 1 mrad, 1.1 mrad]}}"}));
    return run_study(model, {}, RunOptions{.threads = 2});
  };
  const StudyOutcome searched = bronze("search"), followed = bronze("follow");
  ASSERT_EQ(followed.distress.size(), 6u);
  int crossings = 0;
  for (std::size_t k = 0; k < 6; ++k) {
    const DistressRow &f = followed.distress[k], &s = searched.distress[k];
    SCOPED_TRACE(std::to_string(k) + ": " + f.method);
    ASSERT_TRUE(s.failure_load && f.failure_load);
    ASSERT_TRUE(s.criterion && f.criterion);
    EXPECT_EQ(criterion_name(*f.criterion), criterion_name(*s.criterion));
    EXPECT_NEAR(*f.failure_load, *s.failure_load, 0.1 * 0.002 * *s.failure_load);
    crossings += !s.criterion->distress && f.method.starts_with("followed by Newton");
  }
  EXPECT_GE(crossings, 4);
}

// Each point starts from one fixed neighbour: the rows are the same to the last bit on
// one thread and on two.
TEST(FollowedMap, TheRowsDoNotDependOnTheThreadCount) {
  const StudyOutcome one = grid("follow", 1), two = grid("follow", 2);
  EXPECT_EQ(distress_csv(one.distress, one.parameter_columns), distress_csv(two.distress, two.parameter_columns));
}

}  // namespace
}  // namespace twb
