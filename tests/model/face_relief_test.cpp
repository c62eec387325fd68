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
#include "study/accuracy/richardson.h"
#include "study/searches/steady_solver.h"
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

// A grid of the paper's washer annulus with `circumferential` columns.
FilmMesh grid(int circumferential, int radial = 5) { return FilmMesh(0.015, 0.024, radial, circumferential); }

TEST(FaceRelief, GroovesAndLandsOnWholeColumnsOfEveryPitch) {
  // 4 grooves of 2 cells in 24 columns: pitch 6, land 4.
  const FaceRelief relief(grooves(4, 2, 50e-6), grid(24));
  for (int j = 0; j < 24; ++j) {
    const double expected = j % 6 < 2 ? 50e-6 : 0.0;
    EXPECT_EQ(relief.cell_start(0, j), expected) << j;
    EXPECT_EQ(relief.cell_end(0, j), expected) << j;
  }
  // A node on an edge: its control volume's halves lie on either side.
  EXPECT_EQ(relief.across_line(0, 0).before, 0.0);  // the land before the first groove (periodic)
  EXPECT_EQ(relief.across_line(0, 0).after, 50e-6);
  EXPECT_EQ(relief.across_line(0, 2).before, 50e-6);
  EXPECT_EQ(relief.across_line(0, 2).after, 0.0);
  EXPECT_EQ(relief.across_line(0, 1).before, relief.across_line(0, 1).after);
  EXPECT_EQ(relief.across_line(0, 4).before, 0.0);
}

TEST(FaceRelief, ATaperFallsLinearlyFromTheInletAndAStepHoldsItsDepth) {
  // Pitch 8: groove 2 cells, land 6, inlet half of it: 3 cells from the groove's end.
  const FaceRelief taper(grooves(2, 2, 40e-6, {LandShape::taper, 9e-6, 0.5}), grid(16));
  EXPECT_DOUBLE_EQ(taper.cell_start(0, 2), 9e-6);
  EXPECT_DOUBLE_EQ(taper.cell_end(0, 2), 6e-6);
  EXPECT_DOUBLE_EQ(taper.cell_start(0, 4), 3e-6);
  EXPECT_NEAR(taper.cell_end(0, 4), 0.0, 1e-21);
  EXPECT_EQ(taper.cell_start(0, 5), 0.0);
  EXPECT_DOUBLE_EQ(taper.in_cell(0, 3, 0.5), 4.5e-6);  // linear across a column
  // Half-means of a linear relief: ¾ of the way along the column before, ¼ along the one after.
  EXPECT_DOUBLE_EQ(taper.across_line(0, 3).before, 6.75e-6);
  EXPECT_DOUBLE_EQ(taper.across_line(0, 3).after, 5.25e-6);
  const FaceRelief step(grooves(2, 2, 40e-6, {LandShape::step, 5e-6, 0.5}), grid(16));
  for (int j : {2, 3, 4, 10, 11, 12}) EXPECT_EQ(step.cell_start(0, j), 5e-6) << j;
  for (int j : {5, 6, 7, 13, 14, 15}) EXPECT_EQ(step.cell_start(0, j), 0.0) << j;
}

// A groove open at the bore and closed at radial line 2 of 5: cut in rows 0 and 1 only,
// the dam (rows 2 and 3) flat land; the lands' columns unchanged; a groove open at the
// outer rim the other way round.
TEST(FaceRelief, ADamEndsTheGrooveOnARadialLine) {
  for (GrooveOpening open : {GrooveOpening::inner_radius, GrooveOpening::outer_radius}) {
    Grooves g = grooves(4, 2, 50e-6);
    g.closed_at = GrooveDam{open, 0.0195, 0.0195, 2};
    const FaceRelief relief(g, grid(24));
    const bool inner = open == GrooveOpening::inner_radius;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 24; ++j) {
        const bool cut = j % 6 < 2 && (inner ? i < 2 : i >= 2);
        EXPECT_EQ(relief.cell_start(i, j), cut ? 50e-6 : 0.0) << i << ", " << j;
        EXPECT_EQ(relief.in_cell(i, j, 0.3), cut ? 50e-6 : 0.0) << i << ", " << j;
      }
    // The groove's nodes, its dam's line included; a rim node is no groove node when the
    // groove is closed before that rim.
    for (int i = 0; i < 5; ++i) {
      EXPECT_EQ(relief.on_groove(i, 1), inner ? i <= 2 : i >= 2) << i;
      EXPECT_EQ(relief.on_groove(i, 2), inner ? i <= 2 : i >= 2) << i;  // the groove's edge line
      EXPECT_FALSE(relief.on_groove(i, 4)) << i;
    }
    // On the dam's line a circumferential face in the groove's column straddles the groove
    // and the dam; off it, none does.
    const FaceRelief::Halves across = relief.across_row(2, 1);
    EXPECT_EQ(inner ? across.before : across.after, 50e-6);
    EXPECT_EQ(inner ? across.after : across.before, 0.0);
    EXPECT_EQ(relief.across_row(1, 1).before, relief.across_row(1, 1).after);
    EXPECT_EQ(relief.across_row(3, 4).before, 0.0);
  }
}

// A node's control volume: one part off every edge, two halves beside a groove's edge
// line, four quarters where the dam's line meets it; the shares are the parts' areas
// (the outer half of a node's annulus the larger), and the least relief at a node is its
// cells' least.
TEST(FaceRelief, ANodesControlVolumeIsSplitWhereEdgesCrossIt) {
  Grooves g = grooves(4, 2, 50e-6);
  g.closed_at = GrooveDam{GrooveOpening::inner_radius, 0.0195, 0.0195, 2};
  const FilmMesh m = grid(24);
  const FaceRelief relief(g, m);
  auto total = [](const FaceRelief::NodeParts& p) {
    double share = 0.0;
    for (int k = 0; k < p.count; ++k) share += p.share[std::size_t(k)];
    return share;
  };
  const FaceRelief::NodeParts land = relief.node_parts(1, 4);
  EXPECT_EQ(land.count, 1);
  EXPECT_EQ(land.relief[0], 0.0);
  const FaceRelief::NodeParts inside = relief.node_parts(1, 1);
  EXPECT_EQ(inside.count, 1);
  EXPECT_EQ(inside.relief[0], 50e-6);
  const FaceRelief::NodeParts edge = relief.node_parts(1, 2);  // the groove's edge line, below the dam
  ASSERT_EQ(edge.count, 2);
  EXPECT_EQ(edge.relief[0], 50e-6);
  EXPECT_EQ(edge.relief[1], 0.0);
  EXPECT_EQ(edge.share[0], 0.5);
  const FaceRelief::NodeParts dam = relief.node_parts(2, 1);  // inside the groove's columns, on the dam
  ASSERT_EQ(dam.count, 4);
  const double r = m.radius(2), outer = (r + 0.25 * m.dr()) / (2 * r);
  EXPECT_EQ(dam.relief[0], 50e-6);
  EXPECT_EQ(dam.relief[1], 50e-6);
  EXPECT_EQ(dam.relief[2], 0.0);
  EXPECT_EQ(dam.relief[3], 0.0);
  EXPECT_DOUBLE_EQ(dam.share[2] + dam.share[3], outer);
  EXPECT_GT(outer, 0.5);
  EXPECT_DOUBLE_EQ(total(dam), 1.0);
  // The dam's corner with the groove's edge: three of its four cells are land.
  const FaceRelief::NodeParts corner = relief.node_parts(2, 2);
  ASSERT_EQ(corner.count, 4);
  EXPECT_EQ(corner.relief[0], 50e-6);
  EXPECT_EQ(corner.relief[1] + corner.relief[2] + corner.relief[3], 0.0);
  EXPECT_EQ(relief.least_at_node(1, 1), 50e-6);
  EXPECT_EQ(relief.least_at_node(2, 1), 0.0);
  EXPECT_EQ(relief.least_at_node(0, 1), 50e-6);
  // Rim nodes: their one row's halves.
  EXPECT_EQ(relief.node_parts(0, 1).count, 1);
  EXPECT_EQ(relief.node_parts(4, 1).relief[0], 0.0);
}

// A dam stays on its radius on a grid refined by two, and a coarser grid that would put
// it between two node lines cannot hold it.
TEST(FaceRelief, ADamKeepsItsRadiusOnAnotherGrid) {
  Grooves g = grooves(4, 2, 50e-6);
  g.closed_at = GrooveDam{GrooveOpening::inner_radius, 0.0195, 0.0195, 2};
  const std::optional<Grooves> fine = grooves_on_grid(g, {5, 24}, {9, 48});
  ASSERT_TRUE(fine);
  EXPECT_EQ(fine->closed_at->line, 4);
  EXPECT_EQ(fine->cells, 4);
  const std::optional<Grooves> coarse = grooves_on_grid(g, {5, 24}, {3, 24});
  ASSERT_TRUE(coarse);
  EXPECT_EQ(coarse->closed_at->line, 1);
  g.closed_at->line = 3;
  EXPECT_FALSE(grooves_on_grid(g, {5, 24}, {3, 24}));  // line 1.5
  EXPECT_FALSE(grooves_on_grid(g, {9, 24}, {5, 24}));  // line 1.5 again
}

// An error bar's refined mesh holds the same grooves as the coarse one: twice the cells
// per groove and land, the dam on twice its line (once its grooves stayed at the coarse
// cell counts, half as wide, and the dam's line index unchanged, half-way to the bore),
// the grooves BearingModel::on_mesh places.
TEST(FaceRelief, TheErrorBarsRefinedMeshKeepsTheGrooves) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 200.0);
  testing::use_coarse_mesh(s);
  testing::use_four_grooves(s);
  s.washer.grooves->closed_at = GrooveDam{GrooveOpening::inner_radius, 0.0, 0.0, 2};
  const Scene fine = refined_mesh(s);
  ASSERT_TRUE(fine.washer.grooves);
  EXPECT_EQ(fine.washer.grooves->cells, 2 * s.washer.grooves->cells);
  EXPECT_EQ(fine.washer.grooves->closed_at->line, 2 * s.washer.grooves->closed_at->line);
  const BearingModel model(s);
  const std::unique_ptr<BearingModel> on = model.on_mesh(fine.mesh.radial_nodes, fine.mesh.circumferential_nodes);
  EXPECT_EQ(on->scene().washer.grooves->cells, fine.washer.grooves->cells);
  EXPECT_EQ(on->scene().washer.grooves->closed_at->line, fine.washer.grooves->closed_at->line);
}

TEST(FaceRelief, AGridThatDoesNotResolveTheGroovesIsAnInternalError) {
  EXPECT_THROW(FaceRelief(grooves(5, 2, 50e-6), grid(24)), InternalError);  // 24 is no multiple of 5
  EXPECT_THROW(FaceRelief(grooves(4, 6, 50e-6), grid(24)), InternalError);  // no land left
  Grooves dammed = grooves(4, 2, 50e-6);
  dammed.closed_at = GrooveDam{GrooveOpening::inner_radius, 0.024, 0.024, 4};
  EXPECT_THROW(FaceRelief(dammed, grid(24)), InternalError);  // a dam on the rim
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
