// The oil's heat carried by its flow (docs/physics.md section 15): the adiabatic land
// between fed grooves against its closed form, and the heat balance closed with the heat
// the oil carries out, in every state of a load ramp.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <gtest/gtest.h>

#include "../support/solved_film.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "model/convection_effect.h"
#include "physics/average_gap.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

// Grooves fed at ambient pressure and at T_s, no tilt, faces all but insulated (an oil
// conductivity of 1e-8 W/(m K)), no friction heat: along every land the film is the
// parallel Couette film, p = 0, the flux ω r h/2 per unit width, the heat μ(ωr)²/h̄T per
// unit area (the shear over the average gap, docs/physics.md section 6). A free node's
// balance warms the oil entering it by 2 μ ω r² Δθ/(ρ c h h̄T); a land of L cells has L − 1
// free nodes (its edges are the grooves'), so it warms the oil by
//
//     ΔT = 2 μ ω (L − 1) Δθ r² / (ρ c h h̄T)
//
// (the continuous land's 2 μ ω β_l r²/(ρ c h²) with β_l = L Δθ, less the heat of the half
// cells beside the grooves, which their oil takes: first order in the land's cells). With
// the groove's mixing the periodic state enters each land at T_s + κ ΔT/(1 − κ) and leaves
// it at T_s + ΔT/(1 − κ), κ = k Q/(Q + q₀) = k h/(h + ε σ) the carry-over the supply oil
// always in the groove (q₀ = ε (ω r/2) σ Δr) dilutes. Discretely exact in θ; in r the node's heat is its cells'
// bilinear share of μ(ωr)²/h̄T · r, ∫(1 − |x|/Δr)(r + x)³ dx = r³Δr(1 + (Δr/r)²/2), while the
// Couette flux through its faces is exact: the rise is ΔT·(1 + (Δr/r)²/2), to the next
// term, of order (Δr/r)⁴ = 1e-4 at the checked row.
TEST(Convection, TheAdiabaticLandBetweenFedGroovesWarmsTheOilAsTheClosedForm) {
  const int count = 12, pitch = 8, land = 7;
  Scene s = testing::wide_parallel_annulus(100.0, 3000.0);
  s.effects.thermal = true;
  s.effects.convection = true;
  s.lubricant.conductivity = 1e-8;
  s.friction.law = FrictionLaw::constant;
  s.friction.coefficient = 0.0;
  s.mesh.radial_nodes = 11;
  s.mesh.circumferential_nodes = count * pitch;
  Grooves g;
  g.count = count;
  g.cells = pitch - land;
  g.width = g.cells * 2 * std::numbers::pi / s.mesh.circumferential_nodes;
  g.depth = 50e-6;
  s.washer.grooves = g;
  const double k = 0.6, supply = s.operating.ambient + 20.0;
  s.lubricant.supply = OilSupply{0.0, SupplyInlet::grooves, supply, k};
  const testing::SolvedFilm solved = testing::solved_film_and_state(s);
  const FilmFields& f = solved.film;
  const FilmMesh& m = f.mesh;
  const int i = 5;
  const double r = m.radius(i), dtheta = 2 * std::numbers::pi / m.circumferential_nodes();
  const double h = f.gap[std::size_t(m.node(i, 4))];  // mid-land
  const double h_bar = average_gap(h, std::hypot(s.washer.roughness.rq, s.gear.roughness.rq)).value;  // σ below
  const double rho_c = s.lubricant.density_at(s.operating.ambient) * s.lubricant.specific_heat;
  const double closed_form = 2 * s.lubricant.constant_viscosity * s.operating.speed * (land - 1) * dtheta * r * r /
                      (rho_c * h * h_bar);
  const double dr = (m.outer_radius() - m.inner_radius()) / (m.radial_nodes() - 1);
  const double rise = closed_form * (1 + 0.5 * (dr / r) * (dr / r)), tolerance = std::pow(dr / r, 4);
  const double sigma = std::hypot(s.washer.roughness.rq, s.gear.roughness.rq);
  const double carry = k * h / (h + ConvectionEffect::kGrooveFreshShare * sigma);
  for (int groove = 0; groove < count; ++groove) {
    const int first = groove * pitch + g.cells;  // the land's inlet edge line (a groove's)
    const double inlet = f.film_temperature[std::size_t(m.node(i, first))];
    const double outlet = f.film_temperature[std::size_t(m.node(i, first + land - 1))];  // its last free node
    EXPECT_NEAR(inlet - supply, carry * rise / (1 - carry), tolerance * carry * rise / (1 - carry)) << groove;
    EXPECT_NEAR(outlet - supply, rise / (1 - carry), tolerance * rise / (1 - carry)) << groove;
    // Linear along the land: every free node warms the oil alike.
    for (int n = 1; n < land; ++n)
      EXPECT_NEAR(f.film_temperature[std::size_t(m.node(i, first + n))] -
                      f.film_temperature[std::size_t(m.node(i, first + n - 1))],
                  rise / (land - 1), tolerance * rise)
          << groove << ", " << n;
  }
 std::cout << "land rise " << rise << " K (closed form " << closed_form << ") at r = " << r << " m; energy error " << solved.state.energy_error << "\n";
}

// Energy (docs/physics.md section 15): generated = conducted to ambient + carried out by
// the oil, in every state of a load ramp, on the paper's washer (Reynolds cavitation, the
// oil entering at the rims at ambient) and on a grooved washer fed at the bore and in its
// grooves (JFO), its grooves open to the rim and closed by a dam. Every heat row is solved to 1e-10 in kelvin of its node's reference
// conductance, so the imbalance they leave is below 1e-8 of the heat generated; the oil
// carries a share of it that the test requires to be positive.
TEST(Convection, TheHeatBalanceClosesWithTheHeatTheOilCarries) {
  Scene paper = testing::table1_scene(true, true, true, true, 545.0, 200.0);
  testing::use_coarse_mesh(paper);
  Scene grooved = paper;
  testing::use_four_grooves(grooved);
  grooved.washer.grooves->land = {LandShape::taper, 4e-6, 0.5};
  grooved.lubricant.supply = OilSupply{0.5e5, SupplyInlet::both, paper.operating.ambient + 10.0, 0.7};
  // The same grooves closed by a dam at radial line 2 of 5, open at the bore.
  Scene dammed = grooved;
  dammed.washer.grooves->closed_at = GrooveDam{GrooveOpening::inner_radius, 0.0, 0.0, 2};
  for (Scene s : {paper, grooved, dammed}) {
    s.effects.convection = true;
    BearingModel model(s);
    std::vector<double> u;
    ASSERT_TRUE(SteadySolver(model, {}).solve_cold(u).converged);
    for (const double load : {200.0, 260.0, 320.0}) {
      model.set_load(load);
      ASSERT_TRUE(SteadySolver(model, {}).solve(u).converged) << load;
      const BearingState state = model.describe(u);
      const std::optional<double> carried = state.reported_value(ConvectionEffect::kHeatCarried);
      ASSERT_TRUE(carried.has_value());
      std::cout << load << " N: generated " << state.heat_generated << " W, to ambient " << state.heat_to_ambient
                << " W, carried " << *carried << " W, error " << state.energy_error << "\n";
      EXPECT_LT(state.energy_error, 1e-8) << load;
      EXPECT_GT(*carried, 0.0) << load;
      EXPECT_NEAR(state.heat_generated, state.heat_to_ambient + *carried, 1e-8 * state.heat_generated);
    }
  }
}

}  // namespace
}  // namespace twb
