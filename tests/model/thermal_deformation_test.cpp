// Thermal deformation (docs/physics.md section 11): the formulas, what the effect costs in
// unknowns, a converged state's balances with it on, and that a steel that does not
// expand gives the undeformed state. (Its Jacobian is checked with every other effect's
// in jacobian_test.cpp; effect off is the suite's other tests, unchanged.)
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "../support/converged_balances.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "physics/thermal_deformation.h"
#include "solver/natural_continuation.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

TEST(ThermalDeformationPhysics, FaceExpansionOfAPlateWithItsBackAtAmbient) {
  // u = c_ν α t ΔT/2: Table 1's carrier (10 mm, 1.2e-5/K) moves 0.6 µm at 10 K.
  EXPECT_DOUBLE_EQ(face_expansion_per_kelvin(1.2e-5, 10e-3, 0.296, false) * 10.0, 0.6e-6);
  EXPECT_DOUBLE_EQ(face_expansion_per_kelvin(1.2e-5, 10e-3, 0.296, true),
                   (1.296 / 0.704) * face_expansion_per_kelvin(1.2e-5, 10e-3, 0.296, false));
}

TEST(ThermalDeformationPhysics, DishingHasZeroMeanOverTheWasher) {
  const double ri = 5.55e-3, ro = 11.35e-3;
  EXPECT_DOUBLE_EQ(dishing_curvature_per_flux(1.2e-5, 60.5), 1.2e-5 / 60.5);
  // ∫ w 2πr dr over the annulus vanishes (Gauss–Legendre, exact for this quartic).
  const double x[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  double integral = 0, scale = 0;
  for (int k = 0; k < 3; ++k) {
    const double r = 0.5 * (ri + ro) + 0.5 * (ro - ri) * x[k];
    integral += w[k] * dishing_shape(r, ri, ro) * r;
    scale += w[k] * std::abs(dishing_shape(r, ri, ro)) * r;
  }
  EXPECT_LT(std::abs(integral), 1e-14 * scale);
  EXPECT_GT(dishing_shape(ro, ri, ro), 0.0);  // the rim rises towards film 2 for κ̄ > 0
  EXPECT_LT(dishing_shape(ri, ri, ro), 0.0);
}

TEST(ThermalDeformationModel, AddsTwoScalarUnknownsAndNoDenseBlock) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  const BearingModel plain(s);
  s.effects.thermal_deformation = true;
  const BearingModel deformed(s);
  // κ̂ and, with the empirical friction law, the contact force.
  EXPECT_EQ(deformed.size(), plain.size() + 2);
  // The new entries: two bordered rows and columns (each at most the model's size),
  // plus the node shapes' carrier and gear columns where the gap enters a row.
  EXPECT_LT(deformed.pattern().nnz(), 2 * plain.pattern().nnz());
  s.friction.law = FrictionLaw::constant;
  EXPECT_EQ(BearingModel(s).size(), plain.size() + 1);
}

struct Converged {
  BearingState state;
  std::vector<double> u;
};

Converged solve(const Scene& s) {
  BearingModel m(s);
  SteadySolver solver(m, {});
  Converged out;
  const SteadyReport rep = solver.solve_cold(out.u);
  EXPECT_TRUE(rep.converged) << rep.message;
  out.state = m.describe(out.u);
  return out;
}

TEST(ThermalDeformationModel, ConvergedStateMeetsTheBalances) {
  for (const double load : {150.0, 500.0}) {
    Scene s = testing::table1_scene(true, true, true, true, 545.0, load);
    testing::use_coarse_mesh(s);
    s.effects.thermal_deformation = true;
    const Converged c = solve(s);
    testing::expect_balanced(c.state);
    EXPECT_NEAR(c.state.fluid_share + c.state.contact_share, 1.0, 1e-8);
  }
}

TEST(ThermalDeformationModel, SteelThatDoesNotExpandLeavesTheStateAlone) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 300.0);
  testing::use_coarse_mesh(s);
  const Converged plain = solve(s);
  s.effects.thermal_deformation = true;
  for (Component* c : {&s.carrier, &s.washer, &s.gear}) c->material.thermal_expansion = 0.0;
  const Converged still = solve(s);
  // Both solved to 1e-10 in scaled residuals; the states agree to a few times that.
  EXPECT_NEAR(still.state.hmin_over_sigma, plain.state.hmin_over_sigma, 1e-8);
  EXPECT_NEAR(still.state.washer_mean_temperature, plain.state.washer_mean_temperature, 1e-7);
  EXPECT_NEAR(still.state.f_eff, plain.state.f_eff, 1e-9);
  EXPECT_NEAR(still.state.fluid_share, plain.state.fluid_share, 1e-9);
}

// The cold start's homotopy (steady_solver.h): at scale 0 the deformed model is the
// rigid film (its two extra unknowns ride along), and walking the scale to 1 lands on
// the state the deformed film's own pseudo-time reaches from the cold start. All solved
// to 1e-10 in scaled residuals: the states agree to a few times that (as above).
TEST(ThermalDeformationModel, ShapesScaledToZeroAreTheRigidFilm) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  testing::use_coarse_mesh(s);
  const Converged plain = solve(s);
  s.effects.thermal_deformation = true;
  BearingModel m(s);
  m.set_deformation_scale(0.0);
  SteadySolver solver(m, {});
  solver.set_deformation_homotopy(false);  // which would walk the scale to 1
  std::vector<double> u;
  ASSERT_TRUE(solver.solve_cold(u).converged);
  const BearingState rigid = m.describe(u);
  EXPECT_NEAR(rigid.hmin_over_sigma, plain.state.hmin_over_sigma, 1e-8);
  EXPECT_NEAR(rigid.washer_mean_temperature, plain.state.washer_mean_temperature, 1e-7);
  EXPECT_NEAR(rigid.f_eff, plain.state.f_eff, 1e-9);
}

// The homotopy lands on the state of the branch a running bearing follows: the one
// continued up from a light load (50 N, warm steps of 25 N). Constrained faces have
// other steady states at 150 N on 5×24: a hot one (87 °C), which the deformed film's own
// pseudo-time from the cold start finds, and one 1 σ thinner than the branch's, where a
// plain Newton step of the scale from 0.625 to 1 landed before the homotopy checked its
// steps for jumps.
TEST(ThermalDeformationModel, ColdStartByHomotopyIsOnTheBranchFromALightLoad) {
  for (const FaceExpansion faces : {FaceExpansion::free, FaceExpansion::constrained}) {
    SCOPED_TRACE(faces == FaceExpansion::free ? "free faces" : "constrained faces");
    Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
    testing::use_coarse_mesh(s);
    s.effects.thermal_deformation = true;
    s.effects.face_expansion = faces;
    BearingModel m(s);
    std::vector<double> by_homotopy;
    const SteadyReport homotopy = SteadySolver(m, {}).solve_cold(by_homotopy);
    ASSERT_TRUE(homotopy.converged) << homotopy.message;
    EXPECT_EQ(homotopy.strategy, "deformation homotopy");
    EXPECT_EQ(m.deformation_scale(), 1.0);
    testing::expect_balanced(m.describe(by_homotopy));

    // The reference without the homotopy: the deformed film's own cold start at 50 N,
    // then natural continuation in load (with its test for jumps between branches).
    std::vector<double> along;
    m.set_load(50.0);
    SteadySolver light(m, {});
    light.set_deformation_homotopy(false);
    ASSERT_TRUE(light.solve_cold(along).converged);
    NaturalSettings up;
    up.newton = NewtonSettings{};
    const NaturalReport climb = continue_in_parameter(m, along, 50.0, 150.0, up);
    ASSERT_TRUE(climb.reached_target) << climb.message;
    m.set_load(150.0);  // the climb's state is at its target
    // Both states solved to the scaled residual 1e-10: they agree to that times the
    // Jacobian's conditioning, as SteelThatDoesNotExpandLeavesTheStateAlone argues; another
    // branch differs by whole kelvins and tenths of σ.
    const BearingState a = m.describe(by_homotopy), b = m.describe(along);
    EXPECT_NEAR(a.hmin_over_sigma, b.hmin_over_sigma, 1e-8);
    EXPECT_NEAR(a.washer_mean_temperature, b.washer_mean_temperature, 1e-7);
    EXPECT_NEAR(a.f_eff, b.f_eff, 1e-9);
    EXPECT_NEAR(m.dishing_curvature(by_homotopy), m.dishing_curvature(along),
                1e-8 * std::abs(m.dishing_curvature(along)));
  }
}

// A model whose shapes a caller scaled keeps that scale through a cold start (the
// homotopy walks to it, not past it).
TEST(ThermalDeformationModel, ColdStartKeepsACallersDeformationScale) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  testing::use_coarse_mesh(s);
  s.effects.thermal_deformation = true;
  BearingModel m(s);
  m.set_deformation_scale(0.5);
  std::vector<double> half;
  const SteadyReport rep = SteadySolver(m, {}).solve_cold(half);
  ASSERT_TRUE(rep.converged) << rep.message;
  EXPECT_EQ(rep.strategy, "deformation homotopy");
  EXPECT_EQ(m.deformation_scale(), 0.5);
  std::vector<double> r(half.size());
  m.evaluate(half, r, {});
  double largest = 0.0;
  for (double x : r) largest = std::max(largest, std::abs(x));
  EXPECT_LE(largest, 1e-10);
}

TEST(ThermalDeformationModel, HeatThroughTheWasherDishesItsRimTowardsFilm2) {
  // Film 1 slides and makes the heat; what crosses the washer from film 1 to film 2
  // dishes it with its rim towards film 2 (κ̄ > 0).
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  testing::use_coarse_mesh(s);
  s.effects.thermal_deformation = true;
  const Converged c = solve(s);
  const BearingModel m(s);
  EXPECT_GT(m.dishing_curvature(c.u), 0.0);
  // The washer's steady heat balance: what enters through film 1 leaves through film 2,
  // so κ̄ = α q̄/K_w with q̄ the heat through film 1 over the washer area, which the
  // carrier cannot exceed: all the heat generated.
  const double ri = s.washer.inner_radius, ro = s.washer.outer_radius;
  const double bound = 1.2e-5 / 60.5 * c.state.heat_generated / (std::numbers::pi * (ro * ro - ri * ri));
  EXPECT_LT(m.dishing_curvature(c.u), bound);
}

}  // namespace
}  // namespace twb
