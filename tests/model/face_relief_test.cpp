// The washer's face relief (docs/physics.md section 14): where the grooves and the lands'
// inlets lie on the grid, and the unfed grooved film against the closed form it reduces
// to, the Rayleigh step.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "../support/solved_film.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "model/face_relief.h"
#include "study/steady_solver.h"
#include "twb/error_family.h"

namespace twb {
namespace {

Grooves grooves(int count, int cells, double depth, Land land = {}) {
  Grooves g;
  g.count = count;
  g.cells = cells;
  g.depth = depth;
  g.land = land;
  return g;
}

TEST(FaceRelief, GroovesAndLandsOnWholeColumnsOfEveryPitch) {
  // 4 grooves of 2 cells in 24 columns: pitch 6, land 4.
  const FaceRelief relief(grooves(4, 2, 50e-6), 24);
  for (int j = 0; j < 24; ++j) {
    const double expected = j % 6 < 2 ? 50e-6 : 0.0;
    EXPECT_EQ(relief.column_start(j), expected) << j;
    EXPECT_EQ(relief.column_end(j), expected) << j;
  }
  // A node on an edge: its control volume's halves lie on either side.
  EXPECT_EQ(relief.node_halves(0).before, 0.0);  // the land before the first groove (periodic)
  EXPECT_EQ(relief.node_halves(0).after, 50e-6);
  EXPECT_EQ(relief.node_halves(2).before, 50e-6);
  EXPECT_EQ(relief.node_halves(2).after, 0.0);
  EXPECT_EQ(relief.node_halves(1).before, relief.node_halves(1).after);
  EXPECT_EQ(relief.node_halves(4).before, 0.0);
}

TEST(FaceRelief, ATaperFallsLinearlyFromTheInletAndAStepHoldsItsDepth) {
  // Pitch 8: groove 2 cells, land 6, inlet half of it: 3 cells from the groove's end.
  const FaceRelief taper(grooves(2, 2, 40e-6, {LandShape::taper, 9e-6, 0.5}), 16);
  EXPECT_DOUBLE_EQ(taper.column_start(2), 9e-6);
  EXPECT_DOUBLE_EQ(taper.column_end(2), 6e-6);
  EXPECT_DOUBLE_EQ(taper.column_start(4), 3e-6);
  EXPECT_NEAR(taper.column_end(4), 0.0, 1e-21);
  EXPECT_EQ(taper.column_start(5), 0.0);
  EXPECT_DOUBLE_EQ(taper.in_column(3, 0.5), 4.5e-6);  // linear across a column
  // Half-means of a linear relief: ¾ of the way along the column before, ¼ along the one after.
  EXPECT_DOUBLE_EQ(taper.node_halves(3).before, 6.75e-6);
  EXPECT_DOUBLE_EQ(taper.node_halves(3).after, 5.25e-6);
  const FaceRelief step(grooves(2, 2, 40e-6, {LandShape::step, 5e-6, 0.5}), 16);
  for (int j : {2, 3, 4, 10, 11, 12}) EXPECT_EQ(step.column_start(j), 5e-6) << j;
  for (int j : {5, 6, 7, 13, 14, 15}) EXPECT_EQ(step.column_start(j), 0.0) << j;
}

TEST(FaceRelief, AGridThatDoesNotResolveTheGroovesIsAnInternalError) {
  EXPECT_THROW(FaceRelief(grooves(5, 2, 50e-6), 24), InternalError);  // 24 is no multiple of 5
  EXPECT_THROW(FaceRelief(grooves(4, 6, 50e-6), 24), InternalError);  // no land left
}

// An unfed grooved film is a Rayleigh step bearing: across a groove of angle β_g the
// gap is h1 = c + d, across the land β_l it is h2 = c, and along θ the pressure rises
// linearly over the groove to its peak at the converging step and falls linearly over
// the land, by (docs/physics.md section 14)
//
//     Δp = 6 μ U (h1 − h2) L1 L2 / (h1³ L2 + h2³ L1),   U = ω r, L1 = β_g r, L2 = β_l r.
//
// On the grid this is exact in θ (the pressure is linear on each part and each face sees
// one gap, however few the cells). On the annulus it holds up to the radial flows: the
// side leakage, of order (pitch / radial width)², and the rise's own growth with r²,
// of order (pitch / r)² = β². Where the film ruptures at the diverging step (the outer
// half: the rise grows outwards, so oil flows inwards and keeps the inner half's floor
// above ambient) the profile is the step's whole, from p = 0. (The washer sits on the
// carrier by contact; film 2 is thick, h/σ ≈ 13: its load is the film's alone.)
double rayleigh_rise(double mu, double u, double h1, double h2, double l1, double l2) {
  return 6 * mu * u * (h1 - h2) * l1 * l2 / (h1 * h1 * h1 * l2 + h2 * h2 * h2 * l1);
}

struct StepProfile {
  double rise, floor, closed_form, bound;
};

std::vector<StepProfile> unfed_grooves(int count, std::vector<int> rows) {
  const int pitch = 4, groove_cells = 3;
  Scene s = testing::wide_parallel_annulus(100.0, 3000.0);
  s.mesh.radial_nodes = 11;
  s.mesh.circumferential_nodes = count * pitch;
  Grooves g = grooves(count, groove_cells, 6e-6);
  g.width = groove_cells * 2 * std::numbers::pi / s.mesh.circumferential_nodes;
  s.washer.grooves = g;
  const FilmFields f = testing::solved_sliding_film(s);
  const FilmMesh& m = f.mesh;
  std::vector<StepProfile> out;
  for (int i : rows) {
    double peak = 0.0, floor = INFINITY;
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      peak = std::max(peak, f.pressure[std::size_t(m.node(i, j))]);
      floor = std::min(floor, f.pressure[std::size_t(m.node(i, j))]);
    }
    const double r = m.radius(i), beta = 2 * std::numbers::pi / count;
    const double h1 = f.gap[std::size_t(m.node(i, 1))];  // inside a groove
    const double h2 = h1 - g.depth;                     // on a land
    const double l1 = g.width * r, l2 = (beta - g.width) * r;
    out.push_back({peak - floor, floor,
                   rayleigh_rise(s.lubricant.constant_viscosity, s.operating.speed * r, h1, h2, l1, l2),
                   std::pow(beta * r / (m.outer_radius() - m.inner_radius()), 2) + beta * beta});
  }
  return out;
}

TEST(FaceRelief, UnfedGroovesCarryTheRayleighStepsRise) {
  std::vector<double> outer_error;
  for (int count : {24, 48}) {
    // Mid-radius, and 4 mm inside the outer rim, where the film ruptures at every
    // diverging step.
    const std::vector<StepProfile> rows = unfed_grooves(count, {5, 8});
    for (const StepProfile& p : rows)
      std::cout << count << " grooves: rise " << p.rise << " Pa, closed form " << p.closed_form << " Pa, floor "
                << p.floor << " Pa, bound " << p.bound << "\n";
    EXPECT_NEAR(rows[0].rise, rows[0].closed_form, rows[0].bound * rows[0].closed_form) << count;
    // The whole step from ambient: p = 0 at the rupture to the solver's tolerance.
    EXPECT_NEAR(rows[1].floor, 0.0, 1e-8 * rows[1].closed_form) << count;
    outer_error.push_back(std::abs(rows[1].rise / rows[1].closed_form - 1.0));
  }
  // Near the rim its p = 0 lowers the rise over a band about a pitch wide: halving the
  // pitch more than halves the shortfall there.
  EXPECT_LT(outer_error[1], 0.5 * outer_error[0]);
}

}  // namespace
}  // namespace twb
