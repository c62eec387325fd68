// `twb run --set path=value`: overrides change the scene and are validated like the
// file, with errors that name the override instead of a line of the file.
#include <gtest/gtest.h>

#include "scene_test_support.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

using testing::kMinimalScene;
using testing::load_error;
using testing::source_path;
using testing::TempScene;

const std::string kPaper = source_path("configs/jackson_green_2006.yaml");

TEST(SceneOverride, ChangesAQuantityWithItsUnit) {
  const Scene scene = load_scene(kPaper, {"operating.load=800 N", "operating.speed=5200 rpm"});
  EXPECT_EQ(scene.operating.load, 800.0);
  EXPECT_NEAR(scene.operating.speed, 5200 * 2 * 3.14159265358979323846 / 60, 1e-12 * 545);
}

TEST(SceneOverride, ChangesAnInteger) {
  EXPECT_EQ(load_scene(kPaper, {"mesh.radial_nodes=17"}).mesh.radial_nodes, 17);
}

TEST(SceneOverride, ReplacesAWholeList) {
  const Scene scene = load_scene(kPaper, {"effects=[hydrodynamics, asperity_contact]"});
  EXPECT_TRUE(scene.effects.hydrodynamics);
  EXPECT_TRUE(scene.effects.asperity_contact);
  EXPECT_FALSE(scene.effects.flow_factors);
  EXPECT_FALSE(scene.effects.thermal);
}

TEST(SceneOverride, LaterOverrideWins) {
  EXPECT_EQ(load_scene(kPaper, {"operating.load=800 N", "operating.load=900 N"}).operating.load, 900.0);
}

TEST(SceneOverride, CreatesSectionsTheFileDoesNotHave) {
  const TempScene file(kMinimalScene);
  const Scene scene = load_scene(file.path(), {"study.type=load_sweep", "study.load_start=100 N",
                                               "study.load_end=2 kN", "study.load_steps=5"});
  ASSERT_EQ(scene.study.type(), StudyType::load_sweep);
  const LoadGrid& grid = std::get<LoadSweepSettings>(scene.study.settings).grid;
  EXPECT_EQ(grid.loads.start, 100.0);
  EXPECT_EQ(grid.loads.end, 2000.0);
  EXPECT_EQ(grid.load_steps, 5);
}

// The paper's scene shares one steel between the bodies through a YAML anchor; an
// override of the washer's steel must not change the carrier's and the gear's.
TEST(SceneOverride, EditsOnlyThePathItNamesThroughAnchors) {
  const Scene scene = load_scene(kPaper, {"materials.washer.youngs_modulus=110 GPa"});
  EXPECT_EQ(scene.washer.material.youngs_modulus, 110e9);
  EXPECT_EQ(scene.carrier.material.youngs_modulus, 201e9);
  EXPECT_EQ(scene.gear.material.youngs_modulus, 201e9);
  EXPECT_EQ(scene.washer.material.poisson_ratio, 0.296);
}

TEST(SceneOverride, ReplacesAnAliasedMapWithoutTouchingItsAnchor) {
  const Scene scene = load_scene(kPaper, {"materials.washer={youngs_modulus: 110 GPa}"});
  EXPECT_EQ(scene.washer.material.youngs_modulus, 110e9);
  EXPECT_EQ(scene.washer.material.conductivity, 60.5);  // the default, not the anchor's
  EXPECT_EQ(scene.carrier.material.youngs_modulus, 201e9);
  EXPECT_EQ(scene.gear.material.youngs_modulus, 201e9);
}

// An alias inside its own anchor's node makes the tree a cycle with 2^n paths of length
// n; looking for other holders of `operating` along every path never ended.
TEST(SceneOverride, AliasInsideItsOwnAnchorEnds) {
  const TempScene file(std::string(kMinimalScene) + "materials:\n  carrier: &loop {washer: *loop, gear: *loop}\n");
  const InputError error = load_error(file.path(), {"operating.load=800 N"});
  EXPECT_NE(std::string(error.what()).find("unknown key 'washer' in 'materials.carrier'"), std::string::npos)
      << error.what();
}

TEST(SceneOverride, WrongDimensionNamesTheOverride) {
  const InputError error = load_error(kPaper, {"operating.load=800 kg"});
  EXPECT_EQ(error.file(), "--set operating.load");
  EXPECT_EQ(error.line(), 0);
  EXPECT_EQ(error.column(), 16);
  EXPECT_STREQ(error.what(),
               "--set operating.load: error: operating.load: '800 kg' has the dimension of mass, "
               "expected a force convertible to N\n"
               "      | operating.load=800 kg\n"
               "      |                ^");
}

TEST(SceneOverride, OutOfRangeNamesTheOverride) {
  const InputError error = load_error(kPaper, {"mesh.radial_nodes=2"});
  EXPECT_EQ(error.file(), "--set mesh.radial_nodes");
  EXPECT_NE(std::string(error.what()).find("mesh.radial_nodes: 2 is out of range; must be in [3, 1025]"),
            std::string::npos)
      << error.what();
}

TEST(SceneOverride, UnknownKeyIsSuggestedAndPointsAtTheKey) {
  const InputError error = load_error(kPaper, {"operating.lod=800 N"});
  EXPECT_EQ(error.file(), "--set operating.lod");
  EXPECT_EQ(error.column(), 11);
  EXPECT_NE(std::string(error.what()).find("unknown key 'lod' in 'operating'; did you mean 'load'?"),
            std::string::npos)
      << error.what();
}

TEST(SceneOverride, UnknownEffectInAnOverriddenList) {
  const InputError error = load_error(kPaper, {"effects=[hydrodynamics, asperity_contct]"});
  EXPECT_EQ(error.file(), "--set effects");
  EXPECT_EQ(error.column(), 25);
  EXPECT_NE(std::string(error.what()).find("did you mean 'asperity_contact'?"), std::string::npos)
      << error.what();
}

TEST(SceneOverride, ErrorInASectionTheOverrideCreatedNamesIt) {
  const TempScene file(kMinimalScene);
  const InputError error = load_error(file.path(), {"study.type=load_sweep"});
  EXPECT_EQ(error.file(), "--set study.type");
  EXPECT_NE(std::string(error.what()).find("missing required key 'load_start' in 'study'"),
            std::string::npos)
      << error.what();
}

TEST(SceneOverride, MissingEqualsSignIsAMalformedOverride) {
  const InputError error = load_error(kPaper, {"operating.load 800 N"});
  EXPECT_EQ(error.file(), "--set");
  EXPECT_NE(std::string(error.what()).find("'operating.load 800 N' is not a valid override"),
            std::string::npos)
      << error.what();
}

TEST(SceneOverride, EmptyPathSegmentIsAMalformedOverride) {
  const InputError error = load_error(kPaper, {"operating..load=800 N"});
  EXPECT_EQ(error.column(), 11);
  EXPECT_NE(std::string(error.what()).find("a path segment is empty"), std::string::npos) << error.what();
}

TEST(SceneOverride, YamlSyntaxErrorInTheValue) {
  const InputError error = load_error(kPaper, {"effects=[hydrodynamics"});
  EXPECT_EQ(error.file(), "--set effects");
  EXPECT_NE(std::string(error.what()).find("YAML syntax error in the value"), std::string::npos)
      << error.what();
}

// yaml-cpp 0.7 reads a lone ',' as an empty value, which would then be reported as a
// missing value.
TEST(SceneOverride, StrayCommaIsASyntaxErrorInTheValue) {
  const InputError error = load_error(kPaper, {"operating.load=,"});
  EXPECT_EQ(error.file(), "--set operating.load");
  EXPECT_EQ(error.column(), 16);
  EXPECT_NE(std::string(error.what()).find("YAML syntax error in the value: unexpected ','"), std::string::npos)
      << error.what();
}

TEST(SceneOverride, SecondYamlDocumentInTheValueIsRejected) {
  const InputError error = load_error(kPaper, {"operating.load=800 N\n---\n900 N"});
  EXPECT_EQ(error.file(), "--set operating.load");
  EXPECT_NE(std::string(error.what()).find("the value holds 2 YAML documents"), std::string::npos)
      << error.what();
}

TEST(SceneOverride, CannotDescendIntoAScalar) {
  const InputError error = load_error(kPaper, {"operating.load.value=800 N"});
  EXPECT_EQ(error.file(), "--set operating.load.value");
  EXPECT_NE(std::string(error.what()).find("'operating.load' is the value '500 N' in the scene, not a map"),
            std::string::npos)
      << error.what();
}

}  // namespace
}  // namespace twb
