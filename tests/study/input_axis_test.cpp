// A distress map over any input by its scene path (study.parameter.name: a path): each
// value's search is the search of the scene written with that value, to the last bit, and
// a named parameter and its path give the same map under their own column names; a grid
// of several axes keys every row by each.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "study/study_runner.h"
#include "twb/results/distress_table.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

StudyOutcome map_of(const std::vector<std::string>& overrides) {
  std::vector<std::string> all = {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24"};
  all.insert(all.end(), overrides.begin(), overrides.end());
  BearingModel model(load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml", all));
  return run_study(model, {});
}

const std::string kMap = "study={type: distress_map, speeds: [545 rad/s], load_start: 100 N, load_end: 400 N, "
                         "error_estimate: none, parameter: ";

TEST(InputAxis, APathMapsAsItsNamedParameterDoes) {
  const StudyOutcome by_path = map_of({kMap + "{name: geometry.gear.tilt, values: [1 mrad, 3 mrad]}}"});
  const StudyOutcome by_name = map_of({kMap + "{name: gear_tilt, values: [1 mrad, 3 mrad]}}"});
  EXPECT_EQ(by_path.parameter_columns, std::vector<std::string>{"geometry.gear.tilt_rad"});
  EXPECT_EQ(by_name.parameter_columns, std::vector<std::string>{"gear_tilt_rad"});
  ASSERT_EQ(by_path.distress.size(), 2u);
  ASSERT_EQ(by_name.distress.size(), 2u);
  // 1 mrad folds (W_d); 3 mrad heats gradually and fails by the flash point.
  EXPECT_TRUE(by_path.distress[0].distress_load);
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_TRUE(by_path.distress[k].failure_load);
    EXPECT_EQ(by_path.distress[k].distress_load, by_name.distress[k].distress_load);
    EXPECT_EQ(by_path.distress[k].failure_load, by_name.distress[k].failure_load);
    EXPECT_EQ(by_path.distress[k].parameters, by_name.distress[k].parameters);
  }
}

TEST(InputAxis, EachValueIsTheSceneWrittenWithIt) {
  const StudyOutcome map =
      map_of({kMap + "{name: materials.carrier.conductivity, values: [30 W/(m K), 90 W/(m K)]}}"});
  EXPECT_EQ(map.parameter_columns, std::vector<std::string>{"materials.carrier.conductivity_W_m_K"});
  ASSERT_EQ(map.distress.size(), 2u);
  const char* values[] = {"30 W/(m K)", "90 W/(m K)"};
  for (std::size_t k = 0; k < 2; ++k) {
    const StudyOutcome alone = map_of({"study={type: distress_map, speeds: [545 rad/s], load_start: 100 N, load_end: "
                                       "400 N, error_estimate: none}",
                                       std::string("materials.carrier.conductivity=") + values[k]});
    ASSERT_EQ(alone.distress.size(), 1u);
    ASSERT_TRUE(map.distress[k].distress_load);
    EXPECT_EQ(map.distress[k].distress_load, alone.distress[0].distress_load) << values[k];
  }
  // The conductivity moves W_d (docs/physics.md section 16: elasticity about 0.19).
  EXPECT_NE(map.distress[0].distress_load, map.distress[1].distress_load);
}

// A grid (study.parameter: a list of axes): one search per combination of the axes'
// values, the first axis outermost, each row, state and summary line keyed by every axis,
// and each combination's search the search of the scene written with those values, to the
// last bit: the inputs by path are read into the scene before the named ones are set
// (the other order lost a named value: the scene read again forgets it).
TEST(Grid, EachCombinationIsTheSceneWrittenWithIt) {
  const StudyOutcome grid = map_of({kMap + "[{name: gear_tilt, values: [1 mrad, 2 mrad]}, "
                                           "{name: materials.carrier.conductivity, values: [30 W/(m K), 90 W/(m K)]}]}"});
  const std::vector<std::string> columns{"gear_tilt_rad", "materials.carrier.conductivity_W_m_K"};
  EXPECT_EQ(grid.parameter_columns, columns);
  ASSERT_EQ(grid.distress.size(), 4u);
  const std::vector<std::vector<double>> combinations{{1e-3, 30.0}, {1e-3, 90.0}, {2e-3, 30.0}, {2e-3, 90.0}};
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(grid.distress[k].parameters, combinations[k]) << k;
  for (const SolvedState& s : grid.states) EXPECT_EQ(s.parameters.size(), 2u);

  // Each tilt's row of the grid against a map over the conductivity alone at that tilt.
  for (const char* tilt : {"1 mrad", "2 mrad"}) {
    const StudyOutcome alone = map_of({std::string("geometry.gear.tilt=") + tilt,
                                       kMap + "{name: materials.carrier.conductivity, values: [30 W/(m K), 90 W/(m K)]}}"});
    ASSERT_EQ(alone.distress.size(), 2u);
    const std::size_t first = std::string(tilt) == "1 mrad" ? 0 : 2;
    for (std::size_t k = 0; k < 2; ++k) {
      SCOPED_TRACE(std::string(tilt) + ", conductivity " + std::to_string(k));
      const DistressRow &g = grid.distress[first + k], &a = alone.distress[k];
      EXPECT_EQ(g.distress_load, a.distress_load);
      EXPECT_EQ(g.failure_load, a.failure_load);
      EXPECT_EQ(g.parameters.back(), a.parameters.front());
    }
  }
  // The files and the summary name both axes.
  const std::string csv = distress_csv(grid.distress, grid.parameter_columns);
  EXPECT_EQ(csv.rfind("speed_rad_s,gear_tilt_rad,materials.carrier.conductivity_W_m_K,W_fail_N,", 0), 0u) << csv;
  EXPECT_NE(csv.find("\n545,0.002,90,"), std::string::npos) << csv;
  bool named = false;
  for (const std::string& line : summary_lines(grid))
    named = named || line.find("545 rad/s, gear_tilt_rad = 0.002, materials.carrier.conductivity_W_m_K = 90:") !=
                         std::string::npos;
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace twb
