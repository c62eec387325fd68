// The material library (twb/scene/material_library.h, docs/materials.md): a scene takes
// its materials by name, overrides them field by field, and writes them back the same.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "physics/modulus_curve.h"
#include "scene_test_support.h"
#include "twb/scene/material_library.h"
#include "twb/scene/scene_inputs.h"

namespace twb {
namespace {

using testing::expect_same_material;
using testing::kMinimalScene;
using testing::TempScene;

// The library's material as the scene reads it for a body: named, and with its PV
// limit only as the washer (physics §8).
Material as_read(const LibraryMaterial& m, bool washer) {
  Material read = m.properties;
  read.library = m.name;
  if (!washer) read.pv_limit.reset();
  return read;
}

// Every bulk material of the library is a valid material for every body: its values lie
// inside the scene's bounds (physical_bounds.h) and arrive unchanged, but for the PV limit,
// which only the washer's face has (physics §8).
TEST(MaterialLibrary, EveryBulkMaterialReadsAsEachBodyWithItsValues) {
  for (const std::string_view name : library_material_names(MaterialForm::bulk)) {
    SCOPED_TRACE(std::string(name));
    const Scene scene = load_scene_text(
        fmt::format("{}materials: {{carrier: {}, washer: {}, gear: {}}}\n", kMinimalScene, name, name, name), "m.yaml");
    const LibraryMaterial& library = *find_library_material(name);
    expect_same_material(scene.carrier.material, as_read(library, false));
    expect_same_material(scene.washer.material, as_read(library, true));
    expect_same_material(scene.gear.material, as_read(library, false));
  }
}

TEST(MaterialLibrary, AFieldOverridesTheNamedMaterialAndKeepsTheRest) {
  const Scene scene = load_scene_text(std::string(kMinimalScene) +
                                          "materials: {washer: {material: peek, yield_strength: 80 MPa}}\n",
                                      "m.yaml");
  Material expected = as_read(*find_library_material("peek"), true);
  expected.yield_strength = 80e6;
  expect_same_material(scene.washer.material, expected);
  // A body the scene does not name keeps the paper's steel, as before the library.
  expect_same_material(scene.carrier.material, Material{});
}

// A scene that names a library material writes it out (twb check, the results' scene.yaml)
// value by value, its name a comment, so that it reads back the same whatever the library
// holds later.
TEST(MaterialLibrary, TheWrittenSceneReadsBackTheSameMaterials) {
  const Scene scene = load_scene_text(std::string(kMinimalScene) +
                                          "materials: {carrier: bearing_steel, washer: {material: pa46, "
                                          "conductivity: 0.4 W/(m K)}, gear: cusn8}\n",
                                      "m.yaml");
  const std::string written = describe_scene(scene);
  EXPECT_NE(written.find("washer:  # the library's pa46"), std::string::npos) << written;
  EXPECT_EQ(written.find("material:"), std::string::npos) << written;
  const Scene again = load_scene_text(written, "written.yaml");
  for (const auto& [first, second] : {std::pair{&scene.carrier, &again.carrier}, std::pair{&scene.washer, &again.washer},
                                      std::pair{&scene.gear, &again.gear}}) {
    Material unnamed = first->material;
    unnamed.library.clear();
    expect_same_material(second->material, unnamed);
  }
}

// `--set` reaches into a material the scene names alone: the name stands for
// {material: name}, so its other values stay the library's.
TEST(MaterialLibrary, AnOverrideOpensAMaterialGivenByName) {
  const TempScene file(std::string(kMinimalScene) + "materials: {washer: peek, gear: cusn8}\n");
  const Scene scene = load_scene(file.path(), {"materials.washer.youngs_modulus=3 GPa", "materials.gear=pa46"});
  Material expected = as_read(*find_library_material("peek"), true);
  expected.youngs_modulus = 3e9;
  expect_same_material(scene.washer.material, expected);
  expect_same_material(scene.gear.material, as_read(*find_library_material("pa46"), false));
}

// A derived scene's fields go over the material its base names alone: the name stands
// for {material: name} there too, so the base's other values stay the library's.
TEST(MaterialLibrary, ADerivedScenesFieldsGoOverTheBasesNamedMaterial) {
  const TempScene base(std::string(kMinimalScene) + "materials: {washer: peek}\n", "_base");
  const std::string base_name = std::filesystem::path(base.path()).filename().string();
  const TempScene derived(
      fmt::format("extends: {}\nmaterials: {{washer: {{yield_strength: 80 MPa}}}}\n", base_name), "_derived");
  Material expected = as_read(*find_library_material("peek"), true);
  expected.yield_strength = 80e6;
  expect_same_material(load_scene(derived.path()).washer.material, expected);
}

// A named material's values are the scene's inputs like values it writes out
// (scene_inputs.h): a sensitivity or a calibration can take the library's modulus, and
// moving it keeps the library's other values.
TEST(MaterialLibrary, ANamedMaterialsValuesAreTheScenesInputs) {
  const Scene scene =
      load_scene_text(std::string(kMinimalScene) + "materials: {washer: {material: peek, conductivity: 0.3 W/(m K)}}\n",
                      "m.yaml");
  const LibraryMaterial& peek = *find_library_material("peek");
  EXPECT_EQ(scene_input(scene, "materials.washer.youngs_modulus").value, *peek.properties.youngs_modulus);
  EXPECT_EQ(scene_input(scene, "materials.washer.conductivity").value, 0.3);
  const std::vector<std::pair<std::string, double>> moved{{"materials.washer.youngs_modulus", 5e9}};
  Material expected = as_read(peek, true);
  expected.youngs_modulus = 5e9;
  expected.conductivity = 0.3;
  expect_same_material(with_inputs(scene, moved).washer.material, expected);
}

// Every bulk material as a body's, written out (twb check, the results' scene.yaml) and
// read again, is the same material: the written values stand without the library.
TEST(MaterialLibrary, EveryBulkMaterialSurvivesTheWrittenScene) {
  for (const std::string_view name : library_material_names(MaterialForm::bulk)) {
    SCOPED_TRACE(std::string(name));
    const Scene scene = load_scene_text(
        fmt::format("{}materials: {{carrier: {}, washer: {}, gear: {}}}\n", kMinimalScene, name, name, name), "m.yaml");
    const Scene again = load_scene_text(describe_scene(scene), "written.yaml");
    for (const auto& [first, second] : {std::pair{&scene.carrier, &again.carrier},
                                        std::pair{&scene.washer, &again.washer}, std::pair{&scene.gear, &again.gear}}) {
      Material unnamed = first->material;
      unnamed.library.clear();
      expect_same_material(second->material, unnamed);
    }
  }
}

InputError material_error(const std::string& materials) {
  const TempScene file(std::string(kMinimalScene) + materials);
  return testing::load_error(file.path());
}

TEST(MaterialLibrary, AnUnknownNameIsLocatedWithTheClosestAndTheAllowed) {
  const InputError e = material_error("materials:\n  washer: peak\n");
  const std::string what = e.what();
  EXPECT_EQ(e.line(), 8) << what;
  EXPECT_EQ(e.column(), 11) << what;
  EXPECT_NE(what.find("did you mean 'peek'"), std::string::npos) << what;
  EXPECT_NE(what.find("cusn8"), std::string::npos) << what;
}

// A coating is a face's layer (issue: coated faces), never a body's material; the error
// says so and lists the bodies' materials, not the coatings.
TEST(MaterialLibrary, ACoatingIsNotABody) {
  for (const std::string_view coating : library_material_names(MaterialForm::coating)) {
    const InputError e = material_error(fmt::format("materials:\n  washer: {{material: {}}}\n", coating));
    const std::string what = e.what();
    EXPECT_NE(what.find("is a coating"), std::string::npos) << what;
    // The list, up to the end of the message's line (the quoted scene line names the coating).
    const std::size_t list = what.find("one of: ");
    const std::string allowed = what.substr(list, what.find('\n', list) - list);
    for (const std::string_view c : library_material_names(MaterialForm::coating))
      EXPECT_EQ(allowed.find(c), std::string::npos) << what;
    EXPECT_NE(allowed.find("peek"), std::string::npos) << what;
    EXPECT_EQ(e.line(), 8) << what;
  }
  EXPECT_FALSE(library_material_names(MaterialForm::coating).empty());
}

TEST(MaterialLibrary, AListIsNeitherANameNorFields) {
  const std::string what = material_error("materials:\n  washer: [peek]\n").what();
  EXPECT_NE(what.find("materials.washer: a list is neither a library material's name"), std::string::npos) << what;
}

// A material's modulus is its room-temperature one (23 degC) where it has a curve: the
// curve starts there with it, and is one the model can take (physics §23, [M1]).
TEST(MaterialLibrary, ACurveStartsAtTheRoomTemperatureModulus) {
  int curves = 0;
  for (const LibraryMaterial& m : material_library()) {
    if (m.modulus_by_temperature.empty()) continue;
    SCOPED_TRACE(std::string(m.name));
    std::vector<double> t, e;
    for (const ModulusAt& point : m.modulus_by_temperature) {
      t.push_back(point.temperature);
      e.push_back(point.modulus);
    }
    const ModulusCurve curve(t, e);
    EXPECT_NEAR(curve.lowest_temperature(), 296.15, 1e-9);
    // The curve is cubic in ln E (about 22, rounded to 4e-15): exp returns E to that relative error.
    EXPECT_NEAR(curve.at(curve.lowest_temperature()).modulus, m.properties.youngs_modulus,
                1e-14 * m.properties.youngs_modulus);
    ++curves;
  }
  EXPECT_GE(curves, 2);  // PEEK and the carbon-filled PEEK
}

bool is_scene_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::islower(static_cast<unsigned char>(c)) != 0 || std::isdigit(static_cast<unsigned char>(c)) != 0 ||
           c == '_';
  });
}

// What the docs and the E(T) of a polymer rest on: unique scene names, a source for every
// material, moduli over temperature ascending and positive, each coating's thickness.
TEST(MaterialLibrary, EveryEntryIsNamedSourcedAndOrdered) {
  std::set<std::string_view> names;
  for (const LibraryMaterial& m : material_library()) {
    SCOPED_TRACE(std::string(m.name));
    EXPECT_TRUE(is_scene_name(m.name));
    EXPECT_TRUE(names.insert(m.name).second) << "named twice";
    EXPECT_FALSE(m.sources.empty());
    EXPECT_FALSE(m.description.empty());
    for (std::size_t i = 0; i < m.modulus_by_temperature.size(); ++i) {
      EXPECT_GT(m.modulus_by_temperature[i].modulus, 0.0);
      if (i > 0) {
        EXPECT_GT(m.modulus_by_temperature[i].temperature, m.modulus_by_temperature[i - 1].temperature);
      }
    }
    EXPECT_EQ(m.coating_thickness.has_value(), m.form == MaterialForm::coating);
    if (m.coating_thickness) {
      EXPECT_LT(m.coating_thickness->first, m.coating_thickness->second);
    }
  }
  // The docs call paper_steel every body's default: it is the Material a scene gets unnamed.
  expect_same_material(find_library_material("paper_steel")->properties, Material{});
  // The bulk materials come first: the order the docs list them in.
  const auto coating = std::find_if(material_library().begin(), material_library().end(),
                                    [](const LibraryMaterial& m) { return m.form == MaterialForm::coating; });
  EXPECT_TRUE(std::all_of(coating, material_library().end(),
                          [](const LibraryMaterial& m) { return m.form == MaterialForm::coating; }));
}

}  // namespace
}  // namespace twb
