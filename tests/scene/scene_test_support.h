// Shared by the scene tests: where the fixtures are, and scenes written on the fly.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "twb/input_error.h"
#include "twb/scene/scene_loader.h"

namespace twb::testing {

inline std::string source_path(const std::string& relative) {
  return (std::filesystem::path(TWB_SOURCE_DIR) / relative).string();
}

// A scene file in the test's temporary directory, removed with it.
class TempScene {
 public:
  // extension: ".yaml" for a scene, ".csv" for a file a scene names
  explicit TempScene(const std::string& text, const std::string& suffix = "", const std::string& extension = ".yaml") {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("twb_scene_") + info->test_suite_name() + "_" + info->name() + suffix + extension;
    for (char& c : name)
      if (c == '/') c = '_';
    path_ = (std::filesystem::temp_directory_path() / name).string();
    std::ofstream(path_) << text;
  }
  ~TempScene() { std::filesystem::remove(path_); }
  TempScene(const TempScene&) = delete;
  TempScene& operator=(const TempScene&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The smallest valid scene (only the required keys) is kSceneBodies + kSceneOperating.
#define TWB_SCENE_BODIES                                                               \
  "effects: [hydrodynamics, asperity_contact]\n"                                        \
  "geometry:\n"                                                                         \
  "  carrier: {thickness: 10 mm}\n"                                                     \
  "  washer: {inner_diameter: 11.1 mm, outer_diameter: 22.7 mm, thickness: 0.635 mm}\n" \
  "  gear: {inner_diameter: 15.6 mm, outer_diameter: 22.7 mm, thickness: 10 mm}\n"
inline const char* const kSceneBodies = TWB_SCENE_BODIES;
inline const char* const kMinimalScene = TWB_SCENE_BODIES "operating: {load: 1000 N, speed: 545 rad/s}\n";
#undef TWB_SCENE_BODIES

// Every value of two materials, and the library name they started from.
inline void expect_same_material(const Material& a, const Material& b) {
  EXPECT_EQ(a.youngs_modulus, b.youngs_modulus);
  EXPECT_EQ(a.poisson_ratio, b.poisson_ratio);
  EXPECT_EQ(a.yield_strength, b.yield_strength);
  EXPECT_EQ(a.conductivity, b.conductivity);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.specific_heat, b.specific_heat);
  EXPECT_EQ(a.thermal_expansion, b.thermal_expansion);
  EXPECT_EQ(a.max_temperature, b.max_temperature);
  EXPECT_EQ(a.pv_limit, b.pv_limit);
  EXPECT_EQ(a.library, b.library);
  ASSERT_EQ(a.modulus_by_temperature.size(), b.modulus_by_temperature.size());
  for (std::size_t k = 0; k < a.modulus_by_temperature.size(); ++k) {
    EXPECT_EQ(a.modulus_by_temperature[k].temperature, b.modulus_by_temperature[k].temperature);
    EXPECT_EQ(a.modulus_by_temperature[k].modulus, b.modulus_by_temperature[k].modulus);
  }
}

// The InputError thrown by loading `path`, or a failed test.
inline InputError load_error(const std::string& path, const std::vector<std::string>& overrides = {}) {
  try {
    load_scene(path, overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "loading " << path << " did not throw an InputError";
  return InputError("", 0, 0, "(no error)", "");
}

}  // namespace twb::testing
