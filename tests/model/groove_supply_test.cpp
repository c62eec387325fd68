// Oil supplied into the grooves (docs/physics.md section 14): every node on a fed groove
// (inside it or on either edge) holds the supply pressure and is full of oil, so each
// land is a film of its own between two pressure boundaries. Checked against the lands'
// closed forms, and the flows the state reports against the film's mass balance.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "../support/solved_film.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"

namespace twb {
namespace {

// The wide parallel annulus (r = 10 … 30 mm, film 2 sliding at ω) with `count` grooves of
// one cell, 6 µm deep, on a grid of `pitch` cells per groove, fed at p_s.
Scene grooved_annulus(int count, int pitch, double supply_pressure, Land land = {}) {
  Scene s = testing::wide_parallel_annulus(100.0, 3000.0);
  s.mesh.radial_nodes = 11;
  s.mesh.circumferential_nodes = count * pitch;
  Grooves g;
  g.count = count;
  g.cells = 1;
  g.width = 2 * std::numbers::pi / s.mesh.circumferential_nodes;
  g.depth = 6e-6;
  g.land = land;
  s.washer.grooves = g;
  s.lubricant.supply = OilSupply{supply_pressure, SupplyInlet::grooves};
  return s;
}

double largest_pressure(const FilmFields& f) { return *std::max_element(f.pressure.begin(), f.pressure.end()); }

TEST(GrooveSupply, EveryNodeOnAFedGrooveHoldsTheSupplyPressure) {
  const double ps = 3e5;
  const Scene s = grooved_annulus(8, 6, ps);
  const FilmFields f = testing::solved_sliding_film(s);
  const FilmMesh& m = f.mesh;
  int on_grooves = 0;
  for (int i = 1; i < m.radial_nodes() - 1; ++i)
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      // Lines 0 and 1 bound the groove of pitch 0 (column 0); every 6th line after.
      const int in_pitch = j % 6;
      if (in_pitch > 1) continue;
      ++on_grooves;
      // The row p̂ − p_s/p_ref = 0 solved to the residual tolerance 1e-10 in p̂ (p_ref =
      // 3000 N over the annulus, 1.2 MPa): 1e-4 Pa.
      EXPECT_NEAR(f.pressure[std::size_t(m.node(i, j))], ps, 1e-3) << i << ", " << j;
    }
  EXPECT_EQ(on_grooves, 9 * 8 * 2);
}

// With the supply at ambient and no tilt, each land is a parallel film between two
// boundaries at p = 0: its Couette flow enters and leaves it alike, and it carries
// nothing. The same grooves unfed are Rayleigh steps and do carry (face_relief_test).
TEST(GrooveSupply, AParallelLandBetweenGroovesFedAtAmbientCarriesNothing) {
  const FilmFields fed = testing::solved_sliding_film(grooved_annulus(24, 5, 0.0));
  Scene unfed_scene = grooved_annulus(24, 5, 0.0);
  unfed_scene.lubricant.supply.reset();
  const FilmFields unfed = testing::solved_sliding_film(unfed_scene);
  const double rise = largest_pressure(unfed);
  std::cout << "largest pressure: fed " << largest_pressure(fed) << " Pa, unfed " << rise << " Pa\n";
  EXPECT_GT(rise, 1e4);
  // p = 0 solves every balance exactly; the solver's tolerance 1e-10 in p̂ (1.2 MPa) allows 1e-4 Pa.
  EXPECT_LT(largest_pressure(fed), 1e-3);
  EXPECT_GT(*std::min_element(fed.pressure.begin(), fed.pressure.end()), -1e-3);
}

// A stepped land between two grooves fed at ambient is the Rayleigh step bearing with
// both ends at p = 0 (docs/physics.md section 14): the pressure rises linearly over the
// inlet L1 (gap h1 = h + d_s) and falls over the rest L2 (gap h), peaking at the step by
//
//     p_max = 6 μ U (h1 − h2) L1 L2 / (h1³ L2 + h2³ L1),   U = ω r.
//
// Exact in θ on the grid (each face sees one gap); on the annulus it holds up to the
// side leakage, of order (β_l r / (r_o − r_i))², and the rise's growth with r², of order
// β_l²: that sum bounds the relative difference at mid-radius.
struct StepPeak {
  double computed, closed_form, bound;
};

StepPeak step_peak(int count) {
  const int pitch = 6;  // a groove of 1 cell, a land of 5: a step of 3 cells, then 2 flat
  const Scene s = grooved_annulus(count, pitch, 0.0, Land{LandShape::step, 6e-6, 0.6});
  const FilmFields f = testing::solved_sliding_film(s);
  const FilmMesh& m = f.mesh;
  const int i = (m.radial_nodes() - 1) / 2;
  double peak = 0.0;
  for (int j = 0; j < m.circumferential_nodes(); ++j) peak = std::max(peak, f.pressure[std::size_t(m.node(i, j))]);
  const double r = m.radius(i), cell = 2 * std::numbers::pi / m.circumferential_nodes();
  const double h2 = f.gap[std::size_t(m.node(i, 5))];  // the land's flat end, before the next groove
  const double h1 = h2 + 6e-6, l1 = 3 * cell * r, l2 = 2 * cell * r, beta_land = 5 * cell;
  const double closed = 6 * s.lubricant.constant_viscosity * s.operating.speed * r * (h1 - h2) * l1 * l2 /
                        (h1 * h1 * h1 * l2 + h2 * h2 * h2 * l1);
  return {peak, closed, std::pow(beta_land * r / (m.outer_radius() - m.inner_radius()), 2) + beta_land * beta_land};
}

// (The film's gap differs between the two counts while the step's depth does not, so
// the ratio h1/h2, which weights the radial term's effect, differs too: the two errors
// are each held to their bound, not to the square of the angle's ratio. Neither is the
// grid's: 0.8–1.0 % and 0.53–0.55 % on 11, 21 and 41 radial nodes alike.)
TEST(GrooveSupply, AStepLandBetweenFedGroovesIsTheRayleighStep) {
  for (int count : {24, 48}) {
    const StepPeak p = step_peak(count);
    std::cout << count << " grooves: peak " << p.computed << " Pa, closed form " << p.closed_form << " Pa, bound "
              << p.bound << "\n";
    EXPECT_NEAR(p.computed, p.closed_form, p.bound * p.closed_form) << count;
  }
}

// Mass: with the film fed in its grooves and at its bore, tilted so that it ruptures
// behind each land, and mass-conserving cavitation with the cavity at ambient, the oil
// supplied leaves at the two rims. Each node's balance holds to the residual tolerance
// 1e-10 of its flow scale (the flow p_ref drives through its faces), so their sum over
// the film's 9·96 nodes to 1e-7 of it; the supply through the rims' groove faces is
// larger than one node's flow scale, so 1e-7 relative bounds the imbalance.
// The same with grooves closed at mid-radius (a dam, open at the bore): the oil the
// grooves supply now crosses the dam's land to reach the outer rim.
TEST(GrooveSupply, TheOilSuppliedLeavesAtTheRimsWithMassConservingCavitation) {
  for (const bool dammed : {false, true})
  for (const CavitationModel cavitation : {CavitationModel::reynolds, CavitationModel::jfo}) {
    Scene s = grooved_annulus(8, 12, 2e5, Land{LandShape::taper, 4e-6, 0.5});
    if (dammed) s.washer.grooves->closed_at = GrooveDam{GrooveOpening::inner_radius, 20e-3, 20e-3, 5};
    s.lubricant.supply->at = SupplyInlet::both;
    s.effects.cavitation = cavitation;
    s.gear.tilt = 1e-4;
    const testing::SolvedFilm solved = testing::solved_film_and_state(s);
    ASSERT_TRUE(solved.state.flows.has_value());
    const FilmFlows& q = *solved.state.flows;
    std::cout << (dammed ? "dammed, " : "") << (cavitation == CavitationModel::jfo ? "jfo" : "reynolds") << ": supplied " << q.supplied
              << " m3/s, inner " << q.inner << ", outer " << q.outer << ", grooves " << q.grooves
              << "; fluid share " << solved.state.fluid_share << "\n";
    // (With Reynolds' condition and the dam, the film returns more oil to the bore than
    // the grooves supply: the ruptured nodes make the difference. Only JFO must be fed.)
    if (cavitation == CavitationModel::jfo || !dammed) {
      EXPECT_GT(q.supplied, 0.0);
    }
    EXPECT_GT(q.outer, 0.0);
    // The fed bore's inflow is supply: inner is negative, supplied = grooves − inner.
    EXPECT_DOUBLE_EQ(q.supplied, q.grooves - q.inner);
    if (cavitation == CavitationModel::jfo) EXPECT_NEAR(q.supplied, q.outer, 1e-7 * q.supplied);
    // Reynolds' cavitation lets a ruptured node send out more than it receives (w ≥ 0
    // there): the film may gain oil, never lose it.
    else EXPECT_GE(q.outer, q.supplied * (1 - 1e-7));
    EXPECT_GT(solved.state.fluid_share, 0.0);
  }
}

// Grooves closed by a dam at r_c, fed with the bore at p_s, at rest on a parallel film of
// constant viscosity: the nodes of each groove up to its dam's line hold p_s, those
// beyond it do not, and the flow leaving at the rim lies between two annuli's radial
// flows Q(r_f) = π h³ p_s / (6 μ ln(r_o/r_f)) (physics §14): fed at the bore alone
// (r_f = r_i; the grooves only add fed nodes, so by the maximum principle the film's
// pressure is nowhere lower) and fed all round at the dam's radius (r_f = r_c; the
// grooves hold p_s on a part of that ring only, nowhere more). Each bound is the closed
// form's within 1.5 times its midpoint-rule error (oil_supply_test.cpp); the film lies
// well inside both. The grooves open to the rim pass more than the dammed ones.
TEST(GrooveSupply, AtRestADammedGroovePassesLessThanTheRingAtItsDam) {
  const double ps = 2e5;
  auto rested = [&](bool dammed) {
    Scene s = grooved_annulus(8, 12, ps);
    s.operating.speed = 0.0;
    s.lubricant.supply->at = SupplyInlet::both;
    if (dammed) s.washer.grooves->closed_at = GrooveDam{GrooveOpening::inner_radius, 20e-3, 20e-3, 5};
    return testing::solved_film_and_state(s);
  };
  const testing::SolvedFilm dammed = rested(true), open = rested(false);
  const FilmMesh& m = dammed.film.mesh;
  for (int i = 1; i < m.radial_nodes() - 1; ++i) {
    // The groove of pitch 0 lies in column 0, between lines 0 and 1; line 6 is a land's middle.
    const double in_groove = dammed.film.pressure[std::size_t(m.node(i, 0))];
    if (i <= 5) EXPECT_NEAR(in_groove, ps, 1e-3) << i;  // the row's tolerance, as above
    else EXPECT_LT(in_groove, ps * (1.0 - 1e-3)) << i;
  }
  const double h = dammed.film.gap[std::size_t(m.node(7, 6))];
  const double viscosity = grooved_annulus(8, 12, ps).lubricant.constant_viscosity;
  const double ri = m.inner_radius(), ro = m.outer_radius(), rc = m.radius(5), dr = m.dr();
  auto annulus = [&](double rf) { return std::numbers::pi * h * h * h * ps / (6 * viscosity * std::log(ro / rf)); };
  auto midpoint = [&](double rf) { return dr * dr / 24 * (1 / (rf * rf) - 1 / (ro * ro)) / std::log(ro / rf); };
  ASSERT_TRUE(dammed.state.flows && open.state.flows);
  const FilmFlows& q = *dammed.state.flows;
  std::cout << "dammed: supplied " << q.supplied << " m3/s, rim " << q.outer << "; bore alone " << annulus(ri)
            << ", ring at the dam " << annulus(rc) << "; open grooves " << open.state.flows->outer << "\n";
  EXPECT_GT(q.outer, annulus(ri) * (1 + 1.5 * midpoint(ri)));
  EXPECT_LT(q.outer, annulus(rc) * (1 - 1.5 * midpoint(rc)));
  EXPECT_NEAR(q.supplied, q.outer, 1e-7 * q.supplied);  // no rupture at rest: the film keeps its oil
  EXPECT_GT(open.state.flows->outer, q.outer);
}

}  // namespace
}  // namespace twb
