// A film's node gaps (model/film_gap.h) against what the gap is (docs/physics.md sections
// 1, 11 and 14): the plane in the rigid position plus the node shape plus the relief, on
// a solved, tilted, grooved and thermally deformed washer of the coarse test mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "model/film_gap.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

struct Solved {
  BearingModel model;
  std::vector<double> u;
  explicit Solved(const Scene& s) : model(s) {
    if (!SteadySolver(model, {}).solve_cold(u).converged) throw std::runtime_error("no steady state");
  }
};

Scene grooved_deformed() {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  testing::use_coarse_mesh(s);
  testing::use_four_grooves(s);
  s.effects.thermal_deformation = true;
  return s;
}

// Each node's smooth gap is the plane h = c + s·(γx·y − γy·x) − tilt·x at the node plus
// its shape δ; the shape is the film's own (non-zero somewhere on a heated washer). The
// plane is summed here in another order than Film::node_gap's: equal to rounding (a few
// ulps of the clearance, which dominates).
TEST(FilmGap, TheSmoothGapIsThePlanePlusTheShape) {
  const Solved at(grooved_deformed());
  const RigidPosition q = at.model.position(at.u);
  for (const Film& film : at.model.films()) {
    const FilmGap gaps(at.model, at.u, film);
    const FilmMesh& m = film.mesh;
    ASSERT_EQ(gaps.shapes().size(), std::size_t(m.node_count()));
    double largest_shape = 0.0;
    for (int i = 0; i < m.radial_nodes(); ++i)
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        const double x = m.radius(i) * std::cos(m.angle(j)), y = m.radius(i) * std::sin(m.angle(j));
        const double plane = film.clearance(q) - film.imposed_tilt * x + film.sign * (q.gamma_x * y - q.gamma_y * x);
        const int n = m.node(i, j);
        EXPECT_NEAR(gaps.smooth(i, j), plane + gaps.shape(n), 1e-14 * film.clearance(q)) << i << ", " << j;
        largest_shape = std::max(largest_shape, std::abs(gaps.shape(n)));
      }
    EXPECT_GT(largest_shape, 0.0) << "film " << film.number;
  }
}

// On the grooved face (film 2) a node on a groove's edge has two parts whose shares sum to
// one; the field's gap is their share-weighted mean, so it lies between the parts' gaps;
// off the edges a node has one part. The least gap is no more than any node's least side,
// and on the flat film 1 there are no parts to straddle.
TEST(FilmGap, TheReliefsPartsAndTheLeastGap) {
  const Solved at(grooved_deformed());
  int straddling = 0;
  for (const Film& film : at.model.films()) {
    const FilmGap gaps(at.model, at.u, film);
    const FilmMesh& m = film.mesh;
    const double least = gaps.least();
    for (int i = 0; i < m.radial_nodes(); ++i)
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        const FaceRelief::NodeParts parts = gaps.parts(i, j);
        double shares = 0.0, low = INFINITY, high = -INFINITY;
        for (int p = 0; p < parts.count; ++p) {
          shares += parts.share[std::size_t(p)];
          low = std::min(low, gaps.smooth(i, j) + parts.relief[std::size_t(p)]);
          high = std::max(high, gaps.smooth(i, j) + parts.relief[std::size_t(p)]);
        }
        EXPECT_NEAR(shares, 1.0, 1e-15);
        const double mean = gaps.mean(i, j);
        EXPECT_GE(mean, low - 1e-15 * high);
        EXPECT_LE(mean, high + 1e-15 * high);
        EXPECT_LE(least, low) << "film " << film.number << " at " << i << ", " << j;
        if (parts.count > 1) ++straddling;
        if (film.relief.flat()) {
          EXPECT_EQ(parts.count, 1);
        }
      }
  }
  EXPECT_GT(straddling, 0);
}

// Without deformation or relief the least gap is the plane's least on the disc of the
// outer radius, which the rim reaches: no node is below it, and the rim sampled finely
// comes to it within slope·r·(1 − cos(Δθ/2)) ≤ slope·r·Δθ²/8, the sampling's own miss.
TEST(FilmGap, AFlatRigidFilmsLeastGapIsThePlanesOnTheRim) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  testing::use_coarse_mesh(s);
  const Solved at(s);
  const RigidPosition q = at.model.position(at.u);
  for (const Film& film : at.model.films()) {
    const FilmGap gaps(at.model, at.u, film);
    EXPECT_TRUE(gaps.shapes().empty());
    const double least = gaps.least();
    const FilmMesh& m = film.mesh;
    double rim = INFINITY;
    for (int k = 0; k < 100000; ++k)
      rim = std::min(rim, film.node_gap_polar(q, m.outer_radius(), 2.0 * std::numbers::pi * k / 100000.0));
    const GapPlane plane = film.plane(q);
    const double slope = std::hypot(plane.a, plane.b) * m.outer_radius();
    EXPECT_NEAR(rim, least, slope * std::pow(2.0 * std::numbers::pi / 100000.0, 2) / 8.0 + 1e-14 * plane.c);
    for (int i = 0; i < m.radial_nodes(); ++i)
      for (int j = 0; j < m.circumferential_nodes(); ++j) EXPECT_GE(gaps.mean(i, j), least);
  }
}

}  // namespace
}  // namespace twb
