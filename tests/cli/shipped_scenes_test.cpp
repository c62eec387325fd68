// Every scene shipped in configs/ loads and validates (twb check exits 0): a scene
// file that drifts from the schema would otherwise only fail for the user.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

TEST(ShippedScenes, EveryConfigLoadsAndBuildsItsModel) {
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(TWB_SOURCE_DIR) + "/configs")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene s = load_scene(entry.path().string());
    const BearingModel m(s);
    EXPECT_GT(m.size(), 0);
    ++count;
  }
  EXPECT_GE(count, 6);
}

TEST(ShippedScenes, EffectScenesCreateOnlyTheirBlocks) {
  const std::string dir = std::string(TWB_SOURCE_DIR) + "/configs/effects/";
  const BearingModel contact(load_scene(dir + "contact_only_static.yaml"));
  EXPECT_EQ(contact.size(), 4);  // the rigid body only
  const BearingModel film(load_scene(dir + "isothermal_film.yaml"));
  EXPECT_EQ(film.size(), 4 + 7 * 66);  // plus interior pressures of the sliding film
  const BearingModel film2(load_scene(dir + "film2_sliding.yaml"));
  EXPECT_EQ(film2.films()[1].pressure_offset, 4);  // film 2 carries the pressure block
  EXPECT_EQ(film2.films()[0].pressure_offset, -1);
}

}  // namespace
}  // namespace twb
