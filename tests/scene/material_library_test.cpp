// The material library (twb/scene/material_library.h, docs/materials.md): a scene takes
// its materials by name, overrides them field by field, and writes them back the same.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <stdexcept>
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
  // A constant modulus replaces the library's curve (physics §23).
  Material expected = as_read(*find_library_material("peek"), true);
  expected.youngs_modulus = 3e9;
  expected.modulus_by_temperature.clear();
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
// moving it keeps the library's other values. A modulus over temperature is a list, no
// input, and its room-temperature value none either (setting it would drop the curve).
TEST(MaterialLibrary, ANamedMaterialsValuesAreTheScenesInputs) {
  const Scene scene = load_scene_text(
      std::string(kMinimalScene) + "materials: {washer: {material: pa46, conductivity: 0.3 W/(m K)}, gear: peek}\n",
      "m.yaml");
  const LibraryMaterial& pa46 = *find_library_material("pa46");
  EXPECT_EQ(scene_input(scene, "materials.washer.youngs_modulus").value, pa46.properties.youngs_modulus);
  EXPECT_EQ(scene_input(scene, "materials.washer.conductivity").value, 0.3);
  const std::vector<std::pair<std::string, double>> moved{{"materials.washer.youngs_modulus", 5e9}};
  Material expected = as_read(pa46, true);
  expected.youngs_modulus = 5e9;
  expected.conductivity = 0.3;
  expect_same_material(with_inputs(scene, moved).washer.material, expected);
  EXPECT_EQ(scene_input(scene, "materials.gear.yield_strength").value,
            find_library_material("peek")->properties.yield_strength);
  EXPECT_THROW(scene_input(scene, "materials.gear.youngs_modulus"), std::invalid_argument);
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

// A modulus over temperature (physics §23) as a scene gives it: its points kept, its
// room-temperature value (23 degC) the curve's there, which the written scene keeps too.
TEST(MaterialLibrary, ACurveIsReadWithItsRoomTemperatureModulus) {
  const Scene scene = load_scene_text(
      std::string(kMinimalScene) +
          "materials:\n  washer:\n    modulus_by_temperature:\n      - {temperature: 20 degC, modulus: 4 GPa}\n"
          "      - {temperature: 150 degC, modulus: 1 GPa}\n",
      "m.yaml");
  const Material& m = scene.washer.material;
  ASSERT_EQ(m.modulus_by_temperature.size(), 2u);
  EXPECT_EQ(m.modulus_by_temperature[1].modulus, 1e9);
  const std::vector<double> t{m.modulus_by_temperature[0].temperature, m.modulus_by_temperature[1].temperature};
  const std::vector<double> e{4e9, 1e9};
  EXPECT_EQ(m.youngs_modulus, ModulusCurve(t, e).at(296.15).modulus);
  EXPECT_LT(m.youngs_modulus, 4e9);
  EXPECT_GT(m.youngs_modulus, 3.5e9);  // 3 K down a fall of 3 GPa over 130 K, in ln E
  expect_same_material(load_scene_text(describe_scene(scene), "written.yaml").washer.material, m);
}

// Below a curve's first point the modulus is held at it (physics §23): a scene whose
// ambient lies there says so once as it is read, and one whose data cover the ambient
// says nothing.
TEST(MaterialLibrary, AnAmbientBelowTheModulusDataIsAWarning) {
  const auto washer_curve_from = [](const char* first) {
    return load_scene_text(std::string(kMinimalScene) +
                               fmt::format("materials:\n  washer:\n    modulus_by_temperature:\n"
                                           "      - {{temperature: {}, modulus: 4 GPa}}\n"
                                           "      - {{temperature: 150 degC, modulus: 1 GPa}}\n",
                                           first),
                           "m.yaml");
  };
  EXPECT_TRUE(washer_curve_from("20 degC").warnings.empty());
  const Scene cold = washer_curve_from("40 degC");
  ASSERT_EQ(cold.warnings.size(), 1u);
  EXPECT_NE(cold.warnings[0].find("materials.washer.modulus_by_temperature begins at 40.0 degC"), std::string::npos)
      << cold.warnings[0];
}

// A constant modulus and a curve stand for each other: either replaces the other the
// named material, the base scene or the file gives; given side by side they are refused.
TEST(MaterialLibrary, AConstantModulusReplacesACurveAndACurveAConstant) {
  const auto washer = [](const std::string& materials, const std::vector<std::string>& overrides = {}) {
    const TempScene file(std::string(kMinimalScene) + materials);
    return load_scene(file.path(), overrides).washer.material;
  };
  const Material constant = washer("materials: {washer: {material: peek, youngs_modulus: 4 GPa}}\n");
  EXPECT_TRUE(constant.modulus_by_temperature.empty());
  EXPECT_EQ(constant.youngs_modulus, 4e9);
  const Material curved = washer(
      "materials: {washer: {material: pa46, modulus_by_temperature: [{temperature: 23 degC, modulus: 3 GPa}, "
      "{temperature: 100 degC, modulus: 1 GPa}]}}\n");
  EXPECT_EQ(curved.modulus_by_temperature.size(), 2u);
  EXPECT_EQ(curved.youngs_modulus, 3e9);
  const Material set = washer("materials: {washer: peek}\n", {"materials.washer.youngs_modulus=4 GPa"});
  EXPECT_TRUE(set.modulus_by_temperature.empty());
  const Material set_over_file = washer(
      "materials: {washer: {modulus_by_temperature: [{temperature: 23 degC, modulus: 3 GPa}, {temperature: 100 "
      "degC, modulus: 1 GPa}]}}\n",
      {"materials.washer.youngs_modulus=4 GPa"});
  EXPECT_TRUE(set_over_file.modulus_by_temperature.empty());
  EXPECT_EQ(set_over_file.youngs_modulus, 4e9);

  const TempScene base(std::string(kMinimalScene) +
                           "materials: {washer: {modulus_by_temperature: [{temperature: 23 degC, modulus: 3 GPa}, "
                           "{temperature: 100 degC, modulus: 1 GPa}]}}\n",
                       "_base");
  const TempScene derived(fmt::format("extends: {}\nmaterials: {{washer: {{youngs_modulus: 4 GPa}}}}\n",
                                      std::filesystem::path(base.path()).filename().string()),
                          "_derived");
  const Material extended = load_scene(derived.path()).washer.material;
  EXPECT_TRUE(extended.modulus_by_temperature.empty());
  EXPECT_EQ(extended.youngs_modulus, 4e9);

  const InputError both = material_error(
      "materials:\n  washer:\n    youngs_modulus: 4 GPa\n    modulus_by_temperature: [{temperature: 23 degC, "
      "modulus: 3 GPa}, {temperature: 100 degC, modulus: 1 GPa}]\n");
  EXPECT_NE(std::string(both.what()).find("not both"), std::string::npos) << both.what();
  EXPECT_EQ(both.line(), 9) << both.what();
}

// A curve of one point, or one that does not rise in temperature, is refused where it is.
TEST(MaterialLibrary, ACurveMustRiseInTemperatureOverTwoPointsOrMore) {
  const InputError one =
      material_error("materials:\n  washer:\n    modulus_by_temperature: [{temperature: 23 degC, modulus: 3 GPa}]\n");
  EXPECT_NE(std::string(one.what()).find("1 point; a modulus over temperature needs at least two"), std::string::npos)
      << one.what();
  EXPECT_EQ(one.line(), 9) << one.what();
  const InputError falling = material_error(
      "materials:\n  washer:\n    modulus_by_temperature:\n      - {temperature: 100 degC, modulus: 3 GPa}\n"
      "      - {temperature: 23 degC, modulus: 1 GPa}\n");
  EXPECT_NE(std::string(falling.what()).find("must rise in temperature (23.00 degC after 100.00 degC)"),
            std::string::npos)
      << falling.what();
  EXPECT_EQ(falling.line(), 11) << falling.what();
  const InputError soft = material_error(
      "materials:\n  washer:\n    modulus_by_temperature:\n      - {temperature: 23 degC, modulus: 3 GPa}\n"
      "      - {temperature: 100 degC, modulus: 3 kPa}\n");
  EXPECT_NE(std::string(soft.what()).find("modulus"), std::string::npos) << soft.what();
  EXPECT_EQ(soft.line(), 11) << soft.what();
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
    if (m.properties.modulus_by_temperature.empty()) continue;
    SCOPED_TRACE(std::string(m.name));
    std::vector<double> t, e;
    for (const ModulusAt& point : m.properties.modulus_by_temperature) {
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
    for (std::size_t i = 0; i < m.properties.modulus_by_temperature.size(); ++i) {
      EXPECT_GT(m.properties.modulus_by_temperature[i].modulus, 0.0);
      if (i > 0) {
        EXPECT_GT(m.properties.modulus_by_temperature[i].temperature, m.properties.modulus_by_temperature[i - 1].temperature);
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
