// configs/jackson_green_2006.yaml must resolve to the paper's Table 1 in SI.
#include <cmath>

#include <gtest/gtest.h>

#include "scene_test_support.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

using testing::source_path;

#define EXPECT_SI(actual, expected) EXPECT_NEAR((actual), (expected), 1e-12 * std::abs(expected))

class PaperScene : public ::testing::Test {
 protected:
  Scene scene = load_scene(source_path("configs/jackson_green_2006.yaml"));
};

TEST_F(PaperScene, AllFourEffects) {
  EXPECT_TRUE(scene.effects.hydrodynamics);
  EXPECT_EQ(scene.effects.cavitation, CavitationModel::reynolds);
  EXPECT_TRUE(scene.effects.flow_factors);
  EXPECT_TRUE(scene.effects.asperity_contact);
  EXPECT_TRUE(scene.effects.thermal);
  EXPECT_EQ(scene.effects.viscosity_temperature, ViscosityTemperature::surface_mean);
}

TEST_F(PaperScene, GeometryOfTable1) {
  EXPECT_SI(scene.washer.inner_radius, 0.0111 / 2);
  EXPECT_SI(scene.washer.outer_radius, 0.0227 / 2);
  EXPECT_SI(scene.washer.thickness, 6.35e-4);
  EXPECT_EQ(scene.washer.tilt, 0.0);
  EXPECT_SI(scene.gear.inner_radius, 0.0156 / 2);
  EXPECT_SI(scene.gear.outer_radius, 0.0227 / 2);
  EXPECT_SI(scene.gear.thickness, 0.01);
  EXPECT_SI(scene.gear.tilt, 0.002);
  // The carrier's face covers the washer annulus.
  EXPECT_EQ(scene.carrier.inner_radius, scene.washer.inner_radius);
  EXPECT_EQ(scene.carrier.outer_radius, scene.washer.outer_radius);
  EXPECT_SI(scene.carrier.thickness, 0.01);
  EXPECT_EQ(scene.carrier.tilt, 0.0);
}

TEST_F(PaperScene, SteelOfTable1ForEveryBody) {
  for (const Component* body : {&scene.carrier, &scene.washer, &scene.gear}) {
    EXPECT_SI(body->material.youngs_modulus, 201e9);
    EXPECT_SI(body->material.poisson_ratio, 0.296);
    EXPECT_SI(body->material.yield_strength, 0.993e9);
    EXPECT_SI(body->material.conductivity, 60.5);
    EXPECT_SI(body->material.density, 7850.0);
    EXPECT_SI(body->material.specific_heat, 470.0);
    EXPECT_SI(body->roughness.ra, 4.5e-7);
    EXPECT_SI(body->roughness.rq, 5.15e-7);
  }
}

TEST_F(PaperScene, AsperityDefaultsFromTheCombinedSigma) {
  const double sigma = std::sqrt(2.0) * 5.15e-7;
  EXPECT_SI(scene.asperities.summit_radius, 20e-6);
  EXPECT_SI(scene.asperities.summit_sigma, sigma);
  EXPECT_SI(scene.asperities.eta_r_sigma, 0.05);
  EXPECT_SI(scene.asperities.summit_density, 0.05 / (20e-6 * sigma));
}

TEST_F(PaperScene, OilOfTable1) {
  EXPECT_SI(scene.lubricant.conductivity, 0.145);
  EXPECT_EQ(scene.lubricant.viscosity_model, ViscosityModel::roelands);
  EXPECT_SI(scene.lubricant.mu_infinity, 6.31e-5);
  EXPECT_SI(scene.lubricant.g0, 3.545);
  EXPECT_SI(scene.lubricant.s0, 1.053);
}

TEST_F(PaperScene, OperatingPoint) {
  EXPECT_SI(scene.operating.load, 500.0);
  EXPECT_SI(scene.operating.speed, 545.0);
  EXPECT_EQ(scene.operating.sliding, SlidingFilm::carrier_washer);
  EXPECT_SI(scene.operating.ambient, 297.15);
  EXPECT_EQ(scene.friction.law, FrictionLaw::empirical);
}

TEST_F(PaperScene, NumericsStudyAndOutput) {
  EXPECT_EQ(scene.mesh.radial_nodes, 9);
  EXPECT_EQ(scene.mesh.circumferential_nodes, 66);
  EXPECT_EQ(scene.mesh.contact_quadrature, 8);
  EXPECT_SI(scene.solver.residual_tolerance, 1e-10);
  EXPECT_SI(scene.solver.step_tolerance, 1e-14);
  EXPECT_EQ(scene.solver.max_iterations, 200);
  EXPECT_SI(scene.solver.cold_start_film, 3.0);
  ASSERT_EQ(scene.study.type(), StudyType::load_sweep);  // the main job: where it fails
  const LoadRange& loads = std::get<LoadSweepSettings>(scene.study.settings).grid.loads;
  EXPECT_EQ(loads.start, 100.0);
  EXPECT_EQ(loads.end, 400.0);
  EXPECT_EQ(scene.output.directory, "results/jackson_green_2006");
  EXPECT_FALSE(scene.output.fields);
  EXPECT_EQ(scene.source, source_path("configs/jackson_green_2006.yaml"));
}

}  // namespace
}  // namespace twb
