// A distress map over any input by its scene path (study.parameter.name: a path): each
// value's search is the search of the scene written with that value, to the last bit, and
// a named parameter and its path give the same map under their own column names.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "study/study_runner.h"
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
  EXPECT_EQ(by_path.parameter_column, "geometry.gear.tilt_rad");
  EXPECT_EQ(by_name.parameter_column, "gear_tilt_rad");
  ASSERT_EQ(by_path.distress.size(), 2u);
  ASSERT_EQ(by_name.distress.size(), 2u);
  // 1 mrad folds (W_d); 3 mrad heats gradually and fails by the flash point.
  EXPECT_TRUE(by_path.distress[0].distress_load);
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_TRUE(by_path.distress[k].failure_load);
    EXPECT_EQ(by_path.distress[k].distress_load, by_name.distress[k].distress_load);
    EXPECT_EQ(by_path.distress[k].failure_load, by_name.distress[k].failure_load);
    EXPECT_EQ(by_path.distress[k].parameter, by_name.distress[k].parameter);
  }
}

TEST(InputAxis, EachValueIsTheSceneWrittenWithIt) {
  const StudyOutcome map =
      map_of({kMap + "{name: materials.carrier.conductivity, values: [30 W/(m K), 90 W/(m K)]}}"});
  EXPECT_EQ(map.parameter_column, "materials.carrier.conductivity_W_m_K");
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

}  // namespace
}  // namespace twb
