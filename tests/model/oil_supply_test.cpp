// Oil fed at the bore (docs/physics.md section 14): the sliding film's inner edge holds
// the supply pressure. At rest (no Couette flow) on a parallel film of constant
// viscosity, the film is the radial flow of an annulus,
//
//     p(r) = p_s · ln(r_o/r) / ln(r_o/r_i),
//
// which the finite volumes approach at second order in Δr (the face conductances
// r_{i+½}Δθ/Δr sum 1/r where the exact solution integrates it).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "../support/solved_film.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

// The largest error of the film's pressure against the closed form, relative to p_s.
double radial_flow_error(int radial_nodes) {
  // The washer sits on the carrier and on the gear by contact: the supply's film
  // carries only part of the load (about 415 N of 1000 N here), whatever its gap.
  Scene s = testing::wide_parallel_annulus(0.0, 1000.0);
  s.lubricant.supply = OilSupply{5e5};
  s.mesh.radial_nodes = radial_nodes;
  s.mesh.circumferential_nodes = 24;
  const FilmFields f = testing::solved_sliding_film(s);
  const FilmMesh& m = f.mesh;
  const double ps = s.lubricant.supply->pressure, ri = m.inner_radius(), ro = m.outer_radius();
  double worst = 0.0;
  for (int i = 0; i < m.radial_nodes(); ++i)
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      const double exact = ps * std::log(ro / m.radius(i)) / std::log(ro / ri);
      worst = std::max(worst, std::abs(f.pressure[std::size_t(m.node(i, j))] - exact) / ps);
    }
  return worst;
}

TEST(OilSupply, AtRestTheBoreFedFilmIsTheAnnulusRadialFlowToSecondOrder) {
  const double coarse = radial_flow_error(9), fine = radial_flow_error(17);
  std::cout << "largest error / p_s: " << coarse << " (9 radial nodes), " << fine << " (17)\n";
  // Δr = 2.5 mm against r_i = 10 mm: the second-order term (Δr/r)²/12-ish stays below 1e-3.
  EXPECT_LT(coarse, 1e-3);
  // Second order: halving Δr divides the error by about 4 (observed order > 1.8).
  EXPECT_GT(coarse / fine, std::pow(2.0, 1.8));
}

// The flow of the same annulus, Q = π h³ p_s / (6 μ ln(r_o/r_i)), enters at the bore and
// leaves at the rim. The discrete film's is p_s over the sum of its radial faces'
// resistances, Σ Δr/(2π r_{i+½}) · 12μ/h³: the midpoint rule of ∫ dr/(2π r), whose
// error is Δr²/24 · ∫ (1/r)'' dr / (2π) relative to the integral; the test allows 1.5 times that.
TEST(OilSupply, AtRestTheBoreFedFilmPassesTheAnnulusFlow) {
  Scene s = testing::wide_parallel_annulus(0.0, 1000.0);
  s.lubricant.supply = OilSupply{5e5};
  s.mesh.radial_nodes = 9;
  s.mesh.circumferential_nodes = 24;
  const testing::SolvedFilm solved = testing::solved_film_and_state(s);
  const FilmMesh& m = solved.film.mesh;
  const double h = solved.film.gap[std::size_t(m.node(4, 0))], mu = s.lubricant.constant_viscosity;
  const double ri = m.inner_radius(), ro = m.outer_radius(), dr = (ro - ri) / (m.radial_nodes() - 1);
  const double exact = std::numbers::pi * h * h * h * 5e5 / (6 * mu * std::log(ro / ri));
  const double midpoint_error = dr * dr / 24 * (1 / (ri * ri) - 1 / (ro * ro)) / std::log(ro / ri);
  ASSERT_TRUE(solved.state.flows.has_value());
  const FilmFlows& q = *solved.state.flows;
  std::cout << "Q " << q.supplied << " m3/s, closed form " << exact << ", rim " << q.outer << "\n";
  EXPECT_NEAR(q.supplied, exact, 1.5 * midpoint_error * exact);
  EXPECT_EQ(q.supplied, -q.inner);
  EXPECT_EQ(q.grooves, 0.0);
  // Every node's balance to the residual tolerance 1e-10 of its flow scale; 9·24 nodes.
  EXPECT_NEAR(q.outer, q.supplied, 1e-7 * q.supplied);
}

TEST(OilSupply, WithoutSupplyBothEdgesAreAmbient) {
  Scene s = testing::table1_scene(true, false, true, false, 545.0, 500.0);
  testing::use_coarse_mesh(s);
  const BearingModel plain(s);
  for (const Film& f : plain.films()) EXPECT_EQ(f.edge_pressure(0), 0.0);
  s.lubricant.supply = OilSupply{2e5};
  const BearingModel fed(s);
  EXPECT_EQ(fed.sliding_film().edge_pressure(0), 2e5);
  EXPECT_EQ(fed.sliding_film().edge_pressure(fed.sliding_film().mesh.radial_nodes() - 1), 0.0);
}

}  // namespace
}  // namespace twb
