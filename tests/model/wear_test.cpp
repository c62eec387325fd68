// Wear of the sliding film's faces in steady studies (docs/physics.md section 20): the
// effect's unknowns exist only when it is on, a new washer's held depths leave its state
// as it was, and the rates it reports are Archard's law [W1]-[W2] on the asperities'
// contact pressure, checked against the closed forms of §20: a uniformly loaded flat face,
// and the worn volume as the contact's friction power over its coefficient.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>
#include <string>
#include <vector>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"
#include "twb/model/bearing_state.h"

namespace twb {
namespace {

constexpr double kRest = 2e-17, kTurn = 5e-17;  // m³/(N·m), unequal so that the faces are told apart

Scene with_wear(Scene s) {
  s.effects.wear = true;
  s.carrier.roughness.wear_rate = kRest;  // film 1 slides: the carrier rests
  s.washer.roughness.wear_rate = kTurn;   // and the washer turns with the gear
  s.gear.roughness.wear_rate = 3.0 * kTurn;
  return s;
}

Index wear_unknowns(const BearingModel& m) {
  Index n = 0;
  for (const UnknownBlock& b : m.layout().blocks())
    if (b.effect == BlockEffect::wear) n += b.size;
  return n;
}

BearingState solved(const Scene& s) {
  BearingModel model(s);
  std::vector<double> u;
  EXPECT_TRUE(SteadySolver(model, {}).solve_cold(u).converged);
  return model.describe(u);
}

double reported(const BearingState& s, const char* column) {
  const std::optional<double> v = s.reported_value(column);
  EXPECT_TRUE(v.has_value()) << column;
  return v.value_or(NAN);
}

TEST(Wear, OffDeclaresNothingAndOnADepthPerNodeOfTheFaceAtRestAndPerRadiusOfTheTurningFace) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 300.0);
  testing::use_coarse_mesh(s);
  EXPECT_EQ(wear_unknowns(BearingModel(s)), 0);
  const BearingModel worn(with_wear(s));
  EXPECT_EQ(wear_unknowns(worn), 5 * 24 + 5);
  auto named = [](const BearingModel& m, const std::string& name) {
    for (const UnknownBlock& b : m.layout().blocks())
      if (b.name == name) return b.size;
    return Index(0);
  };
  EXPECT_EQ(named(worn, "film 1 worn depth, face at rest"), 5 * 24);
  EXPECT_EQ(named(worn, "film 1 worn depth, turning face"), 5);
  Scene film_2 = with_wear(s);
  film_2.operating.sliding = SlidingFilm::washer_gear;
  EXPECT_EQ(named(BearingModel(film_2), "film 2 worn depth, face at rest"), 5 * 24);
}

// A new washer's depths are zero: the gap is the unworn one, and so is the state, to
// where Newton stopped.
TEST(Wear, HeldAtNoDepthTheStateIsTheNewWashers) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 300.0);
  testing::use_coarse_mesh(s);
  const BearingState unworn = solved(s), worn = solved(with_wear(s));
  for (auto [name, a, b] : {std::tuple{"torque", unworn.torque, worn.torque},
                            std::tuple{"T_max", unworn.max_film_temperature, worn.max_film_temperature},
                            std::tuple{"h_min", unworn.hmin_over_sigma, worn.hmin_over_sigma},
                            std::tuple{"contact share", unworn.contact_share, worn.contact_share}})
    EXPECT_NEAR(a, b, 1e-9 * std::abs(a)) << name;
  EXPECT_EQ(reported(worn, "worn_depth_rest_um"), 0.0);
  EXPECT_EQ(reported(worn, "worn_depth_turn_um"), 0.0);
  EXPECT_GT(reported(worn, "wear_rate_rest_um_h"), 0.0);
  EXPECT_FALSE(unworn.reported_value("wear_rate_rest_um_h"));
}

// A flat washer on its asperities alone (no oil film, no tilt): film 1 carries the load
// W at the uniform pressure p = W/A, and [W1] wears the face at rest at k·p·ω·r. Its
// rate at a node is the lumped mean over the node's hat N_a, k·p·ω·∫r·N_a dA/∫N_a dA
// (so that the worn volume is the depths' exact integral); at the rim, where it wears
// fastest, that mean radius is (r_o²/2 − r_o·Δr/3 + Δr²/12)/(r_o/2 − Δr/6). The turning
// face sees the same pressure at every angle, so the same rate with its own k. The
// quadrature integrates r²·N_a exactly, so the only error is the solve's: the washer
// parallel to Newton's tolerance.
TEST(Wear, ArchardOnAUniformlyLoadedFlatFace) {
  Scene s = testing::table1_scene(false, false, true, false, 545.0, 300.0);
  testing::use_coarse_mesh(s);
  s.gear.tilt = 0.0;
  const BearingState state = solved(with_wear(s));
  const double ri = s.washer.inner_radius, ro = s.washer.outer_radius;
  const double p = s.operating.load / (std::numbers::pi * (ro * ro - ri * ri));
  // Film 2, the narrower annulus the gear overlaps, presses hardest, at W over its area.
  const double r2 = s.gear.inner_radius;
  EXPECT_NEAR(state.max_contact_pressure, p * (ro * ro - ri * ri) / (ro * ro - r2 * r2), 1e-9 * state.max_contact_pressure);
  const double dr = (ro - ri) / (s.mesh.radial_nodes - 1);
  const double rim = (ro * ro / 2 - ro * dr / 3 + dr * dr / 12) / (ro / 2 - dr / 6);
  const double um_per_h = 1e6 * 3600.0;
  const double rest = um_per_h * kRest * p * s.operating.speed * rim;
  EXPECT_NEAR(reported(state, "wear_rate_rest_um_h"), rest, 1e-9 * rest);
  EXPECT_NEAR(reported(state, "wear_rate_turn_um_h"), rest * kTurn / kRest, 1e-9 * rest * kTurn / kRest);
  // Over the whole face, k·p·ω·∫r dA = k·p·ω·(2π/3)(r_o³ − r_i³).
  const double volume = 1e9 * 3600.0 * kRest * p * s.operating.speed * 2.0 * std::numbers::pi / 3.0 *
                        (ro * ro * ro - ri * ri * ri);
  EXPECT_NEAR(reported(state, "wear_volume_rate_rest_mm3_h"), volume, 1e-9 * volume);
}

// [W1]-[W2] remove (k_rest + k_turn)·∫p_c·|V| dA per second, and the contact's friction
// power is f·∫p_c·|V| dA = |ω|·(the contact's friction torque). Without a film pressure or
// heat the contact does not see the oil, whose shear adds a torque linear in its
// viscosity: two viscosities give the contact's torque as 2·T(μ) − T(2μ), and each face's
// volume rate is k·|ω|·(that torque)/f to round-off (the same integrals summed in
// another order), tilted or not, whichever film slides.
TEST(Wear, EachFacesVolumeRateIsItsRateTimesTheContactsFrictionPowerOverTheCoefficient) {
  for (const SlidingFilm sliding : {SlidingFilm::carrier_washer, SlidingFilm::washer_gear}) {
    Scene s = testing::table1_scene(false, false, true, false, 545.0, 300.0);
    testing::use_coarse_mesh(s);
    s.operating.sliding = sliding;
    s.friction.law = FrictionLaw::constant;
    s.friction.coefficient = 0.12;
    s.lubricant.viscosity_model = ViscosityModel::constant;
    s.lubricant.constant_viscosity = 0.01;
    const Scene worn = with_wear(s);
    const BearingState state = solved(worn);
    Scene thicker = worn;
    thicker.lubricant.constant_viscosity *= 2.0;
    const double contact_torque = 2.0 * state.torque - solved(thicker).torque;
    const double power = s.operating.speed * contact_torque / s.friction.coefficient;  // ∫p_c·|V| dA, W
    const bool carrier = sliding == SlidingFilm::carrier_washer;
    const double k_rest = *(carrier ? worn.carrier : worn.washer).roughness.wear_rate;
    const double k_turn = *(carrier ? worn.washer : worn.gear).roughness.wear_rate;
    const double mm3_per_h = 1e9 * 3600.0;
    EXPECT_NEAR(reported(state, "wear_volume_rate_rest_mm3_h"), mm3_per_h * k_rest * power,
                1e-12 * mm3_per_h * k_rest * power);
    EXPECT_NEAR(reported(state, "wear_volume_rate_turn_mm3_h"), mm3_per_h * k_turn * power,
                1e-12 * mm3_per_h * k_turn * power);
    // The tilted gear loads one side: the face at rest wears fastest there, faster than the
    // turning face's mean of the same ring.
    EXPECT_GT(reported(state, "wear_rate_rest_um_h") / k_rest, reported(state, "wear_rate_turn_um_h") / k_turn);
  }
}

}  // namespace
}  // namespace twb
