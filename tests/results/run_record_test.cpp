// run.json: valid JSON, the resolved scene's numbers in SI with the unit in the key (as
// in the CSVs' columns), the solver's counts.
#include "results/run_record.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../scene/scene_test_support.h"
#include "model/bearing_model.h"

namespace twb {
namespace {

using nlohmann::json;

// Every string left in the scene is a name, never a number with a unit.
void expect_no_quantity_strings(const json& node, const std::string& path) {
  if (node.is_object()) {
    for (const auto& [key, value] : node.items()) expect_no_quantity_strings(value, path + "." + key);
  } else if (node.is_array()) {
    for (const json& item : node) expect_no_quantity_strings(item, path);
  } else if (node.is_string()) {
    const std::string s = node.get<std::string>();
    EXPECT_FALSE(!s.empty() && (std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '-')) << path << ": " << s;
  }
}

TEST(RunRecord, SceneNumbersInSiWithTheUnitInTheKey) {
  const Scene scene = load_scene(testing::source_path("configs/studies/distress_map.yaml"));
  const BearingModel model(scene);
  RunTimings t;
  t.newton_iterations = 42;
  t.klu_factorizations = 7;
  t.total_ms = 12.3456789;
  const json run = json::parse(run_json("x.yaml", describe_scene(scene), model.layout(), t, "ok"));
  const json& s = run.at("scene");
  EXPECT_DOUBLE_EQ(s.at("geometry").at("washer").at("thickness_m").get<double>(), 0.635e-3);
  EXPECT_DOUBLE_EQ(s.at("geometry").at("gear").at("tilt_rad").get<double>(), 2e-3);
  EXPECT_DOUBLE_EQ(s.at("operating").at("ambient_K").get<double>(), 297.15);
  EXPECT_DOUBLE_EQ(s.at("materials").at("washer").at("conductivity_W_per_m_K").get<double>(), 60.5);
  EXPECT_DOUBLE_EQ(s.at("materials").at("washer").at("poisson_ratio").get<double>(), 0.296);
  EXPECT_DOUBLE_EQ(s.at("surfaces").at("asperities").at("summit_density_per_m2").get<double>(),
                   scene.asperities.summit_density);
  EXPECT_EQ(s.at("study").at("speeds_rad_s"), json::array({136.0, 545.0, 953.0, 1367.0}));
  EXPECT_EQ(s.at("output").at("fields"), false);
  EXPECT_EQ(s.at("friction").at("law"), "empirical");
  expect_no_quantity_strings(s, "scene");
  EXPECT_EQ(run.at("timings").at("newton_iterations"), 42);
  EXPECT_EQ(run.at("timings").at("klu_factorizations"), 7);
  EXPECT_DOUBLE_EQ(run.at("timings").at("total_ms").get<double>(), 12.346);
  EXPECT_EQ(run.at("unknowns").at("total"), model.size());
  EXPECT_EQ(run.at("outcome"), "ok");
}

}  // namespace
}  // namespace twb
