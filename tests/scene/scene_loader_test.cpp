// Defaults, describe_scene's round trip, and the file-level errors of load_scene.
#include <filesystem>
#include <cmath>
#include <numbers>
#include <ostream>
#include <span>
#include <type_traits>
#include <variant>

#include <gtest/gtest.h>

#include "scene_test_support.h"
#include "twb/scene/scene_inputs.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

using testing::expect_same_material;
using testing::kMinimalScene;
using testing::load_error;
using testing::source_path;
using testing::TempScene;

void expect_same_component(const Component& a, const Component& b) {
  EXPECT_EQ(a.inner_radius, b.inner_radius);
  EXPECT_EQ(a.outer_radius, b.outer_radius);
  EXPECT_EQ(a.thickness, b.thickness);
  EXPECT_EQ(a.tilt, b.tilt);
  expect_same_material(a.material, b.material);
  EXPECT_EQ(a.roughness.ra, b.roughness.ra);
  EXPECT_EQ(a.roughness.rq, b.roughness.rq);
  EXPECT_EQ(a.roughness.wear_rate, b.roughness.wear_rate);
  EXPECT_EQ(a.roughness.run_in_rq, b.roughness.run_in_rq);
  ASSERT_EQ(a.grooves.has_value(), b.grooves.has_value());
  if (!a.grooves) return;
  EXPECT_EQ(a.grooves->count, b.grooves->count);
  EXPECT_EQ(a.grooves->film, b.grooves->film);
  EXPECT_EQ(a.grooves->width, b.grooves->width);
  EXPECT_EQ(a.grooves->written_width, b.grooves->written_width);
  EXPECT_EQ(a.grooves->depth, b.grooves->depth);
  EXPECT_EQ(a.grooves->cells, b.grooves->cells);
  EXPECT_EQ(a.grooves->land.shape, b.grooves->land.shape);
  EXPECT_EQ(a.grooves->land.depth, b.grooves->land.depth);
  EXPECT_EQ(a.grooves->land.fraction, b.grooves->land.fraction);
}

// A calibration's settings read back: its data file by its absolute path, its points by
// their load and speed, its fitted inputs and spreads to the last digits written.
void expect_same_calibration(const CalibrationSettings& a, const CalibrationSettings& b) {
  if (!a.data.empty() || !b.data.empty()) {
    EXPECT_EQ(std::filesystem::absolute(a.data), std::filesystem::absolute(b.data));
  }
  ASSERT_EQ(a.measurements.size(), b.measurements.size());
  for (std::size_t i = 0; i < a.measurements.size(); ++i) {
    EXPECT_EQ(a.measurements[i].load, b.measurements[i].load);
    EXPECT_EQ(a.measurements[i].speed, b.measurements[i].speed);
  }
  ASSERT_EQ(a.fitted.size(), b.fitted.size());
  for (std::size_t i = 0; i < a.fitted.size(); ++i) {
    const FittedInput &x = a.fitted[i], &y = b.fitted[i];
    EXPECT_EQ(x.path, y.path);
    EXPECT_DOUBLE_EQ(x.start, y.start);
    EXPECT_DOUBLE_EQ(x.lower, y.lower);
    EXPECT_DOUBLE_EQ(x.upper, y.upper);
  }
  for (std::size_t q = 0; q < kMeasuredQuantities; ++q) EXPECT_DOUBLE_EQ(a.measurement_sd[q], b.measurement_sd[q]);
  EXPECT_EQ(a.fit_iterations, b.fit_iterations);
}

// The same study type with the same settings, every member of them (a calibration's as
// above).
void expect_same_study(const Study& a, const Study& b) {
  ASSERT_EQ(a.type(), b.type());
  std::visit(
      [&](const auto& x) {
        using Settings = std::decay_t<decltype(x)>;
        const Settings& y = std::get<Settings>(b.settings);
        if constexpr (std::is_same_v<Settings, CalibrationSettings>)
          expect_same_calibration(x, y);
        else
          EXPECT_TRUE(x == y) << "the study's settings differ";
      },
      a.settings);
}

// Every field but `source`.
void expect_same_scene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.effects.hydrodynamics, b.effects.hydrodynamics);
  EXPECT_EQ(a.effects.cavitation, b.effects.cavitation);
  EXPECT_EQ(a.effects.cavity_pressure, b.effects.cavity_pressure);
  EXPECT_EQ(a.effects.flow_factors, b.effects.flow_factors);
  EXPECT_EQ(a.effects.asperity_contact, b.effects.asperity_contact);
  EXPECT_EQ(a.effects.thermal, b.effects.thermal);
  EXPECT_EQ(a.effects.viscosity_temperature, b.effects.viscosity_temperature);
  EXPECT_EQ(a.effects.carrier_temperature, b.effects.carrier_temperature);
  EXPECT_EQ(a.effects.thermal_deformation, b.effects.thermal_deformation);
  EXPECT_EQ(a.effects.face_expansion, b.effects.face_expansion);
  expect_same_component(a.carrier, b.carrier);
  expect_same_component(a.washer, b.washer);
  expect_same_component(a.gear, b.gear);
  EXPECT_EQ(a.asperities.summit_radius, b.asperities.summit_radius);
  EXPECT_EQ(a.asperities.summit_sigma, b.asperities.summit_sigma);
  EXPECT_EQ(a.asperities.summit_density, b.asperities.summit_density);
  EXPECT_EQ(a.asperities.eta_r_sigma, b.asperities.eta_r_sigma);
  EXPECT_EQ(a.lubricant.conductivity, b.lubricant.conductivity);
  EXPECT_EQ(a.lubricant.viscosity_model, b.lubricant.viscosity_model);
  EXPECT_EQ(a.lubricant.mu_infinity, b.lubricant.mu_infinity);
  EXPECT_EQ(a.lubricant.g0, b.lubricant.g0);
  EXPECT_EQ(a.lubricant.s0, b.lubricant.s0);
  EXPECT_EQ(a.lubricant.constant_viscosity, b.lubricant.constant_viscosity);
  ASSERT_EQ(a.lubricant.supply.has_value(), b.lubricant.supply.has_value());
  if (a.lubricant.supply) {
    EXPECT_EQ(a.lubricant.supply->pressure, b.lubricant.supply->pressure);
    EXPECT_EQ(a.lubricant.supply->at, b.lubricant.supply->at);
    EXPECT_EQ(a.lubricant.supply->temperature, b.lubricant.supply->temperature);
    EXPECT_EQ(a.lubricant.supply->carry_over, b.lubricant.supply->carry_over);
  }
  EXPECT_EQ(a.lubricant.density, b.lubricant.density);
  EXPECT_EQ(a.lubricant.density_expansion, b.lubricant.density_expansion);
  EXPECT_EQ(a.lubricant.specific_heat, b.lubricant.specific_heat);
  EXPECT_EQ(a.effects.convection, b.effects.convection);
  EXPECT_EQ(a.effects.wear, b.effects.wear);
  EXPECT_EQ(a.limits.min_film_ratio, b.limits.min_film_ratio);
  EXPECT_EQ(a.limits.scuffing_temperature, b.limits.scuffing_temperature);
  EXPECT_EQ(a.limits.wear_depth, b.limits.wear_depth);
  EXPECT_EQ(a.operating.load, b.operating.load);
  EXPECT_EQ(a.operating.speed, b.operating.speed);
  EXPECT_EQ(a.operating.sliding, b.operating.sliding);
  EXPECT_EQ(a.operating.ambient, b.operating.ambient);
  EXPECT_EQ(a.friction.law, b.friction.law);
  EXPECT_EQ(a.friction.coefficient, b.friction.coefficient);
  EXPECT_EQ(a.mesh.radial_nodes, b.mesh.radial_nodes);
  EXPECT_EQ(a.mesh.circumferential_nodes, b.mesh.circumferential_nodes);
  EXPECT_EQ(a.mesh.contact_quadrature, b.mesh.contact_quadrature);
  EXPECT_EQ(a.solver.residual_tolerance, b.solver.residual_tolerance);
  EXPECT_EQ(a.solver.step_tolerance, b.solver.step_tolerance);
  EXPECT_EQ(a.solver.max_iterations, b.solver.max_iterations);
  EXPECT_EQ(a.solver.cold_start_film, b.solver.cold_start_film);
  expect_same_study(a.study, b.study);
  EXPECT_EQ(a.mesh.max_refinements, b.mesh.max_refinements);
  EXPECT_EQ(a.output.directory, b.output.directory);
  EXPECT_EQ(a.output.fields, b.output.fields);
}

TEST(SceneDefaults, OmittedKeysTakeTheDefaultsOfSceneH) {
  const TempScene file(kMinimalScene);
  const Scene scene = load_scene(file.path());
  const Scene defaults;
  expect_same_material(scene.washer.material, defaults.washer.material);
  EXPECT_EQ(scene.gear.roughness.rq, defaults.gear.roughness.rq);
  EXPECT_EQ(scene.gear.tilt, 0.0);
  EXPECT_EQ(scene.lubricant.viscosity_model, ViscosityModel::roelands);
  EXPECT_EQ(scene.lubricant.mu_infinity, defaults.lubricant.mu_infinity);
  EXPECT_EQ(scene.operating.sliding, SlidingFilm::carrier_washer);
  EXPECT_EQ(scene.operating.ambient, 297.15);
  EXPECT_EQ(scene.friction.law, FrictionLaw::empirical);
  EXPECT_EQ(scene.mesh.radial_nodes, 9);
  EXPECT_EQ(scene.solver.max_iterations, 200);
  ASSERT_EQ(scene.study.type(), StudyType::point);
  EXPECT_TRUE(std::get<PointSettings>(scene.study.settings) == PointSettings{});
  EXPECT_EQ(scene.output.directory, "results");
  EXPECT_FALSE(scene.effects.flow_factors);
  EXPECT_FALSE(scene.effects.thermal);
  EXPECT_EQ(scene.asperities.summit_sigma, std::hypot(0.515e-6, 0.515e-6));
}

TEST(SceneDefaults, SummitDensityGivenDirectlySetsEtaRSigma) {
  const TempScene file(std::string(kMinimalScene) +
                       "surfaces: {asperities: {summit_radius: 10 um, summit_sigma: 0.5 um, "
                       "summit_density: 1e10 1/m^2}}\n");
  const Scene scene = load_scene(file.path());
  EXPECT_EQ(scene.asperities.summit_density, 1e10);
  EXPECT_NEAR(scene.asperities.eta_r_sigma, 1e10 * 10e-6 * 0.5e-6, 1e-15);
}

// Grooves put every edge on a node line (docs/physics.md section 14): the circumferential
// count becomes the nearest multiple of the groove count, the width and the land's
// inlet whole cells of it.
TEST(SceneGrooves, EdgesOnNodeLinesRoundTheGridAndTheWidths) {
  const std::string bodies(testing::kSceneBodies);
  auto grooved = [&](const std::string& grooves, const std::string& mesh) {
    std::string text = bodies;
    text.replace(text.find("thickness: 0.635 mm}"), 20, "thickness: 0.635 mm, grooves: " + grooves + "}");
    return TempScene(text + "operating: {load: 1000 N, speed: 545 rad/s, sliding: washer_gear}\n" + mesh);
  };
  // 66 nodes, 8 grooves: 64 (8 per pitch). 2 mm at the mean radius 8.45 mm is 0.2367 rad,
  // 2.41 cells of 2π/64: 2 cells.
  const Scene eight = load_scene(grooved("{count: 8, width: 2 mm, depth: 50 um}", "").path());
  ASSERT_TRUE(eight.washer.grooves);
  EXPECT_EQ(eight.mesh.circumferential_nodes, 64);
  EXPECT_EQ(eight.washer.grooves->cells, 2);
  EXPECT_DOUBLE_EQ(eight.washer.grooves->width, 2 * 2 * std::numbers::pi / 64);
  EXPECT_EQ(eight.washer.grooves->film, 2);
  EXPECT_EQ(eight.washer.grooves->land.shape, LandShape::flat);
  // 100 nodes, 7 grooves: 98 (14 per pitch); 30 degrees is 8.17 cells of 2π/98: 8; the
  // taper over 0.3 of the 6-cell land: 2 cells, 1/3.
  const Scene seven = load_scene(
      grooved("{count: 7, width: 30 deg, depth: 20 um, land: {taper: {depth: 5 um, fraction: 0.3}}}",
              "mesh: {circumferential_nodes: 100}\n")
          .path());
  EXPECT_EQ(seven.mesh.circumferential_nodes, 98);
  EXPECT_EQ(seven.washer.grooves->cells, 8);
  EXPECT_EQ(seven.washer.grooves->land.shape, LandShape::taper);
  EXPECT_DOUBLE_EQ(seven.washer.grooves->land.fraction, 2.0 / 6.0);
  // A groove nearly as wide as the pitch (14 of 15 degrees: 2.8 cells of the 3 a pitch
  // gets) keeps one cell of land, a step one cell of flat land; one at least as wide as
  // the pitch is refused (malformed_scenes.h).
  const Scene wide = load_scene(
      grooved("{count: 24, width: 14 deg, depth: 20 um, land: {step: {depth: 5 um, fraction: 0.9}}}", "").path());
  EXPECT_EQ(wide.mesh.circumferential_nodes, 72);
  EXPECT_EQ(wide.washer.grooves->cells, 1);
  EXPECT_DOUBLE_EQ(wide.washer.grooves->land.fraction, 0.5);
}

// A load grid without `speeds` runs at operating.speed; with them, at each of them.
// A scene's speeds of one search each, as its searches read them.
std::vector<double> speeds(const Scene& scene) {
  const std::span<const double> listed = scene.study.speeds();
  return {listed.begin(), listed.end()};
}

TEST(SceneDefaults, LoadSweepSpeedsDefaultToTheOperatingSpeed) {
  const std::string sweep = "study: {type: load_sweep, load_start: 100 N, load_end: 1750 N, load_steps: 34";
  const TempScene plain(std::string(kMinimalScene) + sweep + "}\n");
  const Scene scene = load_scene(plain.path());
  EXPECT_EQ(speeds(scene), std::vector<double>{scene.operating.speed});
  EXPECT_TRUE(scene.study.axes().empty());
  EXPECT_EQ(speeds(load_scene(plain.path(), {"operating.speed=953 rad/s"})), std::vector<double>{953.0});
  const TempScene listed(std::string(kMinimalScene) + sweep + ", speeds: [136 rad/s, 1367 rad/s]}\n");
  EXPECT_EQ(speeds(load_scene(listed.path())), (std::vector<double>{136.0, 1367.0}));
  const TempScene choice(std::string(kMinimalScene) +
                         "study: {type: sliding_choice, load_start: 100 N, load_end: 1750 N, load_steps: 34}\n");
  EXPECT_EQ(load_scene(choice.path()).study.type(), StudyType::sliding_choice);
  EXPECT_EQ(speeds(load_scene(choice.path())), std::vector<double>{load_scene(choice.path()).operating.speed});
}

struct RoundTripCase {
  std::string name;
  std::string text;
};
void PrintTo(const RoundTripCase& c, std::ostream* os) { *os << c.name; }

// A transient study needs the thermal effect (it marches the heat balance).
std::string with_thermal(std::string scene, const std::string& thermal = "thermal") {
  const std::string effects = "effects: [hydrodynamics, asperity_contact]";
  return scene.replace(scene.find(effects), effects.size(),
                       "effects: [hydrodynamics, asperity_contact, " + thermal + "]");
}

class DescribeRoundTrip : public ::testing::TestWithParam<RoundTripCase> {};

TEST_P(DescribeRoundTrip, DescribedSceneLoadsBackIdentically) {
  const TempScene original(GetParam().text);
  const Scene first = load_scene(original.path());
  const std::string text = describe_scene(first);
  const TempScene described(text, "_described");
  const Scene second = load_scene(described.path());
  SCOPED_TRACE(text);
  expect_same_scene(first, second);
  // Apart from the header comments, describing is idempotent.
  const auto body = [](const std::string& described) { return described.substr(described.find("\neffects:")); };
  EXPECT_EQ(body(describe_scene(second)), body(text));
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, DescribeRoundTrip,
    ::testing::Values(
        RoundTripCase{"minimal", kMinimalScene},
        RoundTripCase{"constant_viscosity_and_friction_load_sweep",
                      std::string(kMinimalScene) +
                          "lubricant: {viscosity: {model: constant, value: 30 mPa s}}\n"
                          "friction: {law: constant, coefficient: 0.15}\n"
                          "study: {type: load_sweep, load_start: 100 N, load_end: 2 kN, load_steps: 20}\n"
                          "output: {directory: 'out dir/with \"quotes\" # and hash', fields: true}\n"},
        RoundTripCase{"distress_map_over_roughness",
                      std::string(kMinimalScene) +
                          "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 1 kN,\n"
                          "        parameter: {name: roughness, values: [0.3 um, 0.515 um, 1 um]}}\n"},
        RoundTripCase{"load_sweep_over_speeds_and_friction",
                      std::string(kMinimalScene) +
                          "friction: {law: constant, coefficient: 0.1}\n"
                          "study: {type: load_sweep, speeds: [136 rad/s, 953 rad/s], load_start: 100 N, load_end: 1750 N,\n"
                          "        load_steps: 34, parameter: {name: friction_coefficient, values: [0.05, 0.2]}}\n"},
        RoundTripCase{"distress_map_over_a_grid",
                      std::string(kMinimalScene) +
                          "friction: {law: constant, coefficient: 0.1}\n"
                          "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 1 kN,\n"
                          "        parameter: [{name: friction_coefficient, values: [0.05, 0.2]},\n"
                          "                    {name: geometry.gear.tilt, values: [1 mrad, 2 mrad, 3 mrad]}]}\n"},
        RoundTripCase{"load_sweep_to_a_tolerance",
                      std::string(kMinimalScene) +
                          "mesh: {max_refinements: 3}\n"
                          "study: {type: load_sweep, load_start: 100 N, load_end: 400 N, load_steps: 4, tolerance: 0.5 %}\n"},
        RoundTripCase{"distress_map_without_a_tolerance",
                      std::string(kMinimalScene) +
                          "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 1 kN,\n"
                          "        tolerance: none}\n"},
        RoundTripCase{"point_to_a_tolerance",
                      std::string(kMinimalScene) + "study: {type: point, tolerance: 2 %}\n"},
        RoundTripCase{"distress_curve_to_a_tolerance",
                      std::string(kMinimalScene) +
                          "study: {type: distress_curve, parameter: speed, from: 100 rad/s, to: 500 rad/s,\n"
                          "        load_start: 100 N, load_end: 2000 N, tolerance: 3 %}\n"},
        RoundTripCase{"point_with_its_two_mesh_bar", std::string(kMinimalScene) + "study: {type: point}\n"},
        RoundTripCase{"point_without_an_error_bar",
                      std::string(kMinimalScene) + "study: {type: point, error_estimate: none}\n"},
        RoundTripCase{"distress_map_searched_on_past_failure",
                      std::string(kMinimalScene) +
                          "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 1 kN,\n"
                          "        search_past_failure: 3.5}\n"},
        RoundTripCase{"distress_map_searched_to_its_end",
                      std::string(kMinimalScene) +
                          "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 1 kN,\n"
                          "        search_past_failure: none}\n"},
        RoundTripCase{"sliding_choice",
                      std::string(kMinimalScene) +
                          "study: {type: sliding_choice, speeds: [545 rad/s, 953 rad/s], load_start: 100 N,\n"
                          "        load_end: 1750 N, load_steps: 34, bracket_width: 0.004}\n"},
        RoundTripCase{"transient_load_step",
                      with_thermal(kMinimalScene) +
                          "study: {type: transient, load_start: 150 N, load_end: 0.2 kN, duration: 2 min}\n"},
        // eta_R_sigma is written as a summit density: its product must read back to the bit.
        RoundTripCase{"rougher_washer_default_summits",
                      std::string(kMinimalScene) + "surfaces: {washer: {Rq: 0.257 um}}\n"},
        RoundTripCase{"output_directory_with_control_characters",
                      std::string(kMinimalScene) + "output: {directory: \"line\\nbreak\\ttab\\x01\\x7f end\"}\n"},
        RoundTripCase{"washer_pv_limit",
                      std::string(kMinimalScene) + "materials: {washer: {pv_limit: 1.8 MPa m/s}}\n"},
        RoundTripCase{"thermal_options",
                      with_thermal(kMinimalScene, "{thermal: {viscosity_temperature: film_node, "
                                                  "carrier_temperature: axisymmetric}}")},
        RoundTripCase{"thermal_deformation_constrained",
                      with_thermal(kMinimalScene, "thermal, {thermal_deformation: {face_expansion: constrained}}") +
                          "materials: {carrier: {thermal_expansion: 11.5e-6 1/K}}\n"},
        RoundTripCase{"grooved_washer_tapered_lands",
                      std::string(testing::kSceneBodies).replace(std::string(testing::kSceneBodies).find("thickness: 0.635 mm}"), 20,
                                                        "thickness: 0.635 mm, grooves: {count: 6, width: 2 mm, "
                                                        "depth: 40 um, land: {taper: {depth: 8 um, fraction: 0.6}}}}") +
                          "operating: {load: 1000 N, speed: 545 rad/s, sliding: washer_gear}\n"},
        RoundTripCase{"grooved_washer_stepped_lands_on_film_1",
                      std::string(testing::kSceneBodies).replace(std::string(testing::kSceneBodies).find("thickness: 0.635 mm}"), 20,
                                                        "thickness: 0.635 mm, grooves: {count: 12, width: 15 deg, "
                                                        "depth: 0.1 mm, face: film_1, land: {step: {depth: 10 um, "
                                                        "fraction: 0.5}}}}") +
                          "operating: {load: 1000 N, speed: 545 rad/s, sliding: washer_gear}\n"},
        RoundTripCase{"oil_supply_at_the_bore_and_into_the_grooves",
                      std::string(testing::kSceneBodies).replace(std::string(testing::kSceneBodies).find("thickness: 0.635 mm}"), 20,
                                                        "thickness: 0.635 mm, grooves: {count: 8, width: 2 mm, "
                                                        "depth: 50 um}}") +
                          "lubricant: {supply: {pressure: 2 bar, at: both}}\n"
                          "operating: {load: 1000 N, speed: 545 rad/s, sliding: washer_gear}\n"},
        RoundTripCase{"grooves_closed_by_a_dam_open_at_the_outer_rim",
                      std::string(testing::kSceneBodies).replace(std::string(testing::kSceneBodies).find("thickness: 0.635 mm}"), 20,
                                                        "thickness: 0.635 mm, grooves: {count: 8, width: 2 mm, "
                                                        "depth: 50 um, closed_at: 9.6 mm, open_at: outer_radius}}") +
                          "lubricant: {supply: {pressure: 2 bar, at: grooves}}\n"
                          "operating: {load: 1000 N, speed: 545 rad/s, sliding: washer_gear}\n"},
        RoundTripCase{"followed_distress_map",
                      std::string(kMinimalScene) + "study: {type: distress_map, method: follow, speeds: [545 rad/s], "
                                                   "load_start: 100 N, load_end: 2000 N, parameter: {name: "
                                                   "friction_coefficient, values: [0.1, 0.2]}}\n"
                                                   "friction: {law: constant, coefficient: 0.2}\n"},
        RoundTripCase{"convection_with_a_cool_supply",
                      with_thermal(kMinimalScene, "thermal, convection") +
                          "lubricant: {density: 870 kg/m^3, specific_heat: 1950 J/(kg K), supply: {pressure: 1 bar, "
                          "at: inner_radius, temperature: 60 degC, carry_over: 0.5}}\n"},
        RoundTripCase{"distress_maps_over_the_grooves",
                      std::string(testing::kSceneBodies).replace(std::string(testing::kSceneBodies).find("thickness: 0.635 mm}"), 20,
                                                        "thickness: 0.635 mm, grooves: {count: 8, width: 2 mm, "
                                                        "depth: 50 um}}") +
                          "operating: {load: 1000 N, speed: 545 rad/s, sliding: washer_gear}\n"
                          "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 3 kN,\n"
                          "        parameter: {name: groove_count, values: [4, 6, 12]}}\n"},
        RoundTripCase{"distress_map_over_the_groove_width",
                      std::string(testing::kSceneBodies).replace(std::string(testing::kSceneBodies).find("thickness: 0.635 mm}"), 20,
                                                        "thickness: 0.635 mm, grooves: {count: 8, width: 2 mm, "
                                                        "depth: 50 um}}") +
                          "operating: {load: 1000 N, speed: 545 rad/s, sliding: washer_gear}\n"
                          "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 3 kN,\n"
                          "        parameter: {name: groove_width, values: [1 mm, 10 deg]}}\n"},
        RoundTripCase{"distress_map_over_the_groove_depth",
                      std::string(testing::kSceneBodies).replace(std::string(testing::kSceneBodies).find("thickness: 0.635 mm}"), 20,
                                                        "thickness: 0.635 mm, grooves: {count: 8, width: 2 mm, "
                                                        "depth: 50 um}}") +
                          "operating: {load: 1000 N, speed: 545 rad/s, sliding: washer_gear}\n"
                          "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 3 kN,\n"
                          "        parameter: {name: groove_depth, values: [10 um, 0.1 mm]}}\n"},
        RoundTripCase{"sensitivity_at_the_point",
                      std::string(kMinimalScene) + "study: {type: sensitivity}\n"},
        RoundTripCase{"sensitivity_of_the_fold_to_named_inputs",
                      std::string(kMinimalScene) +
                          "study: {type: sensitivity, load_start: 100 N, load_end: 400 N, bracket_width: 0.001,\n"
                          "        parameters: [geometry.gear.tilt, surfaces.washer.Rq, materials.carrier.thermal_expansion]}\n"},
        RoundTripCase{"reliability_of_every_distribution",
                      std::string(kMinimalScene) +
                          "study: {type: reliability, load_start: 100 N, load_end: 1500 N, bracket_width: 0.001,\n"
                          "        inputs: {operating.ambient: {distribution: normal, sd: 3 degC},\n"
                          "                 geometry.gear.tilt: {distribution: truncated_normal, sd: 0.3 mrad, lower: 1 mrad,\n"
                          "                                      upper: 3 mrad},\n"
                          "                 surfaces.asperities.summit_radius: {distribution: lognormal, sd: 4 um},\n"
                          "                 materials.carrier.conductivity: {distribution: uniform, lower: 45 W/(m K),\n"
                          "                                                  upper: 60 W/(m K)}},\n"
                          "        probabilities: [1e-4, 0.01], monte_carlo: {cov: 0.05, max_samples: 500, seed: 7}}\n"},
        RoundTripCase{"calibration_with_spreads",
                      std::string(kMinimalScene) + "study: {type: calibration, data: '" +
                          source_path("tests/scene/data/calibration_rig.csv") +
                          "',\n        fit: {geometry.gear.tilt: {start: 1.5 mrad, lower: 0.5 mrad, upper: 2.5 mrad},\n"
                          "              surfaces.asperities.summit_radius: {lower: 10 um, upper: 40 um}},\n"
                          "        sd: {torque: 2 N mm, T_mean: 0.5 degC}, max_iterations: 12}\n"},
        RoundTripCase{"distress_map_over_an_input_by_its_path",
                      std::string(kMinimalScene) +
                          "study: {type: distress_map, speeds: [545 rad/s], load_start: 50 N, load_end: 3 kN,\n"
                          "        parameter: {name: materials.carrier.conductivity, values: [30 W/(m K), 90 W/(m K)]}}\n"},
        RoundTripCase{"oil_supply_at_the_bore",
                      std::string(kMinimalScene) + "lubricant: {supply: {pressure: 3.5 bar, at: inner_radius}}\n"},
        RoundTripCase{"mass_conserving_cavitation",
                      std::string(kMinimalScene).replace(std::string(kMinimalScene).find("[hydrodynamics"), 14,
                                                         "[{hydrodynamics: {cavitation: jfo, cavity_pressure: -0.3 bar}}")},
        RoundTripCase{"wear_with_its_rates_and_allowance",
                      std::string(kMinimalScene).replace(std::string(kMinimalScene).find("asperity_contact]"), 17,
                                                         "asperity_contact, wear]") +
                          "surfaces: {carrier: {wear_rate: 2e-17 m^3/(N m), run_in_rq: 0.2 um}, washer: {wear_rate: 0},\n"
                          "           gear: {wear_rate: 3e-7 mm^3/(N m)}}\n"
                          "limits: {wear_depth: 25 um}\n"},
        RoundTripCase{"distress_map_custom_surfaces_film_2",
                      std::string(testing::kSceneBodies) +
                          "study: {type: distress_map, speeds: [136 rad/s, 5200 rpm], load_start: 50 N, load_end: 3 kN,\n"
                          "        parameter: {name: gear_tilt, values: [1 mrad, 2 mrad, 4e-3]}, bracket_width: 0.001}\n"
                          "surfaces: {asperities: {summit_density: 3e11 1/m^2}, gear: {Rq: 0.3 um}}\n"
                          "materials: {washer: {youngs_modulus: 110 GPa, poisson_ratio: 0.34}}\n"
                          "operating: {load: 800 N, speed: 953 rad/s, sliding: washer_gear, ambient: 80 degC}\n"}),
    [](const auto& info) { return info.param.name; });

TEST(DescribeScene, PaperSceneRoundTripsAndNamesItsSource) {
  const std::string path = source_path("configs/jackson_green_2006.yaml");
  const Scene first = load_scene(path);
  const std::string text = describe_scene(first);
  EXPECT_NE(text.find(path), std::string::npos);
  EXPECT_NE(text.find("load: 500 N"), std::string::npos);
  EXPECT_NE(text.find("ambient: 297.15 K"), std::string::npos);
  const TempScene described(text, "_described");
  expect_same_scene(first, load_scene(described.path()));
}

TEST(SceneFile, MissingFileIsNamed) {
  const InputError error = load_error("/no/such/dir/scene.yaml");
  EXPECT_EQ(error.file(), "/no/such/dir/scene.yaml");
  EXPECT_EQ(error.line(), 0);
  EXPECT_NE(std::string(error.what()).find("cannot open the scene file '/no/such/dir/scene.yaml'"),
            std::string::npos)
      << error.what();
}

TEST(SceneFile, DirectoryIsNotAScene) {
  const InputError error = load_error(source_path("configs"));
  EXPECT_NE(std::string(error.what()).find("is a directory"), std::string::npos) << error.what();
}

TEST(SceneFile, EmptyFileNeedsTheRequiredKeys) {
  const TempScene file("# nothing here\n");
  const InputError error = load_error(file.path());
  EXPECT_EQ(error.line(), 1);
  EXPECT_NE(std::string(error.what()).find("missing required key 'effects' at the top level"),
            std::string::npos)
      << error.what();
}

TEST(SceneFile, ASecondYamlDocumentIsRejected) {
  const TempScene file(std::string(kMinimalScene) + "---\nmesh: {radial_nodes: 17}\n");
  const InputError error = load_error(file.path());
  EXPECT_EQ(error.line(), 8);
  EXPECT_NE(std::string(error.what()).find("2 YAML documents"), std::string::npos) << error.what();
}

// yaml-cpp 0.7's LoadAll never returns on this (its issue 1040): the test would hang.
TEST(SceneFile, StrayCommaAfterTheSceneIsASyntaxError) {
  const TempScene file(std::string(kMinimalScene) + "---\n,\n");
  const InputError error = load_error(file.path());
  EXPECT_EQ(error.line(), 8);
  EXPECT_EQ(error.column(), 1);
  EXPECT_NE(std::string(error.what()).find("YAML syntax error: unexpected ','"), std::string::npos) << error.what();
}

// yaml-cpp's character positions do not count a byte order mark: the comma is found by
// its line and column.
TEST(SceneText, StrayCommaAfterAByteOrderMarkIsNamed) {
  try {
    load_scene_text("\xef\xbb\xbf# scene\n,\n", "bom.yaml");
    ADD_FAILURE() << "a stray comma was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), 2);
    EXPECT_EQ(error.message(), "YAML syntax error: unexpected ','");
  }
}

TEST(SceneText, LoadsLikeTheFileAndNamesTheGivenSource) {
  const TempScene file(kMinimalScene);
  const Scene from_text = load_scene_text(kMinimalScene, "inline scene", {"operating.load=800 N"});
  expect_same_scene(load_scene(file.path(), {"operating.load=800 N"}), from_text);
  EXPECT_EQ(from_text.source, "inline scene");
  EXPECT_EQ(from_text.operating.load, 800.0);
  try {
    load_scene_text("effects: [hydrodynamics]\ngeometry: [1, 2\n", "inline scene");
    ADD_FAILURE() << "a YAML syntax error was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "inline scene");
    EXPECT_GT(error.line(), 0);
  }
}

TEST(InputErrorFormat, QuotesTheLineWithACaretUnderTheColumn) {
  const InputError error("configs/bad.yaml", 12, 11, "unknown key 'thicknes'", "  washer: {thicknes: 0.635 mm}");
  EXPECT_STREQ(error.what(),
               "configs/bad.yaml:12:11: error: unknown key 'thicknes'\n"
               "   12 |   washer: {thicknes: 0.635 mm}\n"
               "      |           ^");
  EXPECT_EQ(error.file(), "configs/bad.yaml");
  EXPECT_EQ(error.line(), 12);
  EXPECT_EQ(error.column(), 11);
  EXPECT_EQ(error.message(), "unknown key 'thicknes'");
}

// The tolerance a scene's error bars are wanted to.
double tolerance(const Scene& scene) {
  const ErrorBarSettings* bars = scene.study.error_bars();
  if (!bars) {
    ADD_FAILURE() << "the study has no error bars";
    return -1.0;
  }
  return bars->tolerance;
}

// study.tolerance: a relative number with its unit or none; refused where no error bar is
// asked for, and outside (0, 0.5], each at its place.
TEST(SceneLoader, ATolerancesValueAndWhereItIsRefused) {
  const std::string sweep = std::string(kMinimalScene) + "study: {type: load_sweep, load_start: 100 N, load_end: 400 N, load_steps: 4";
  EXPECT_EQ(tolerance(load_scene_text(sweep + "}\n", "t.yaml")), 0.01);  // the default
  EXPECT_DOUBLE_EQ(tolerance(load_scene_text(sweep + ", tolerance: 2 %}\n", "t.yaml")), 0.02);
  EXPECT_EQ(tolerance(load_scene_text(sweep + ", tolerance: none}\n", "t.yaml")), 0.0);
  const auto refused = [&](const std::string& text, const std::string& needle) {
    try {
      load_scene_text(text, "t.yaml");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("t.yaml:"), std::string::npos) << e.what();
    }
  };
  refused(sweep + ", error_estimate: none, tolerance: 1 %}\n", "error_estimate: none asks for no error bar");
  refused(sweep + ", tolerance: 0}\n", "study.tolerance");
  refused(sweep + ", tolerance: 60 %}\n", "study.tolerance");
  refused(sweep + ", tolerance: 1 N}\n", "study.tolerance");
  refused(std::string(kMinimalScene) + "study: {type: sensitivity, tolerance: 1 %}\n", "tolerance");
  // A point takes one, none by default (its two-mesh bar).
  EXPECT_EQ(tolerance(load_scene_text(std::string(kMinimalScene) + "study: {type: point}\n", "t.yaml")), 0.0);
  EXPECT_DOUBLE_EQ(
      tolerance(load_scene_text(std::string(kMinimalScene) + "study: {type: point, tolerance: 2 %}\n", "t.yaml")),
      0.02);
  refused(std::string(kMinimalScene) + "mesh: {max_refinements: 6}\n", "mesh.max_refinements");
  // A distress curve takes one (its folds and limit curves to it), 1 % by default.
  const std::string curve = std::string(kMinimalScene) +
                            "study: {type: distress_curve, parameter: speed, from: 100 rad/s, to: 500 rad/s, "
                            "load_start: 100 N, load_end: 2000 N";
  EXPECT_EQ(tolerance(load_scene_text(curve + "}\n", "t.yaml")), 0.01);
  EXPECT_DOUBLE_EQ(tolerance(load_scene_text(curve + ", tolerance: 3 %}\n", "t.yaml")), 0.03);
  refused(curve + ", error_estimate: none, tolerance: 1 %}\n", "error_estimate: none asks for no error bar");
}

// materials.washer.pv_limit: a PV in its unit, the washer's only, refused elsewhere and
// in another unit, at its place.
TEST(SceneLoader, APVLimitIsTheWashersInItsUnit) {
  EXPECT_DOUBLE_EQ(*load_scene_text(std::string(kMinimalScene) + "materials: {washer: {pv_limit: 1.8 MPa m/s}}\n",
                                    "pv.yaml")
                        .washer.material.pv_limit,
                   1.8e6);
  for (const char* bad : {"materials: {carrier: {pv_limit: 1.8 MPa m/s}}\n",
                          "materials: {washer: {pv_limit: 1.8 MPa}}\n", "materials: {washer: {pv_limit: 0}}\n"}) {
    try {
      load_scene_text(std::string(kMinimalScene) + bad, "pv.yaml");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("pv_limit"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("pv.yaml:"), std::string::npos) << e.what();
    }
  }
}

// A face's Ra rides along with its Rq (physics §16): Ra enters no equation but may not
// exceed Rq, so the bronze washer's Ra 0.35 um would refuse any Rq below it. Setting Rq
// scales Ra by the same factor (the face's texture kept), unless Ra is set too; and a
// lognormal Rq reaching below the scene's Ra within its four standard deviations is
// accepted.
TEST(SceneLoader, AnUncertainRqCarriesItsFacesRaAlong) {
  const std::string bronze = std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_cusn8.yaml";
  const Scene scene = load_scene(bronze);
  const double ra = scene.washer.roughness.ra, rq = scene.washer.roughness.rq;
  const std::pair<std::string, double> lower[] = {{"surfaces.washer.Rq", 0.6 * ra}};
  const Scene rougher = with_inputs(scene, lower);
  EXPECT_DOUBLE_EQ(rougher.washer.roughness.rq, 0.6 * ra);
  EXPECT_NEAR(rougher.washer.roughness.ra, ra * (0.6 * ra / rq), 1e-15 * ra);
  // Ra set alone moves nothing the model reads (a sensitivity to it is nought).
  const std::pair<std::string, double> ra_only[] = {{"surfaces.washer.Ra", 0.9 * ra}};
  EXPECT_EQ(with_inputs(scene, ra_only).washer.roughness.rq, rq);
  const std::pair<std::string, double> both[] = {{"surfaces.washer.Rq", 0.6 * ra}, {"surfaces.washer.Ra", 0.5 * ra}};
  EXPECT_DOUBLE_EQ(with_inputs(scene, both).washer.roughness.ra, 0.5 * ra);
  // Both set, Ra above Rq: still refused, at the override.
  const std::pair<std::string, double> wrong[] = {{"surfaces.washer.Rq", 0.6 * ra}, {"surfaces.washer.Ra", ra}};
  EXPECT_THROW(with_inputs(scene, wrong), InputError);
  const Scene reliability = load_scene(
      bronze, {"study={type: reliability, load_start: 100 N, load_end: 1500 N, "
               "inputs: {surfaces.washer.Rq: {distribution: lognormal, sd: 0.05 um}}, probabilities: [0.01]}"});
  const std::vector<UncertainInput>& inputs = std::get<ReliabilitySettings>(reliability.study.settings).uncertain_inputs;
  ASSERT_EQ(inputs.size(), 1u);
  EXPECT_EQ(inputs.front().path, "surfaces.washer.Rq");
}

}  // namespace
}  // namespace twb
