// Cells where the contact pressure varies by less than a factor e^½ are integrated with
// the flat rule (mesh.flat_contact_quadrature, 6 × 6) instead of the contact rule
// (8 × 8). The flat rule's error there is below 1e-15 of the cell's contact force
// (film_loads.cpp), so the residual may differ from the contact rule's everywhere only
// by the rounding of sums over different points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

struct Case { double speed, load; };
class FlatContactRule : public ::testing::TestWithParam<Case> {};

TEST_P(FlatContactRule, ChangesTheResidualOnlyByRounding) {
  const Case c = GetParam();
  Scene s = testing::table1_scene(true, true, true, true, c.speed, c.load);
  BearingModel flat(s);
  SteadySolver solver(flat, {});
  std::vector<double> u;
  ASSERT_TRUE(solver.solve_cold(u).converged);
  // Film 2 has no pressure: it carries the whole load by contact, and below distress
  // it is nearly parallel, so its cells are flat (ln p varies by 0.1–0.4 across each).

  s.mesh.flat_contact_quadrature = s.mesh.contact_quadrature;  // the contact rule everywhere
  const BearingModel full(s);
  std::vector<double> r_flat(u.size()), r_full(u.size());
  flat.evaluate(u, r_flat, {});
  full.evaluate(u, r_full, {});
  // Rows are scaled by the load (forces) or a node conductance (heat): a rule error
  // of 1e-15 of the contact force is 1e-15 in the rigid-body rows. Summing the film's
  // 528 cells × 64 points (terms of size ~1 in all) rounds like √N·ε (at worst N·ε):
  // √33792·2.2e-16 = 4e-14; ten times that allows for the cells' own sums. A 3 × 3 flat
  // rule (residuals 3e-10 apart at 136 rad/s) fails this.
  double largest = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    EXPECT_NEAR(r_flat[k], r_full[k], 4e-13) << flat.block_name(Index(k)) << ", row " << k;
    largest = std::max(largest, std::abs(r_flat[k] - r_full[k]));
  }
  // Not vacuous: the flat rule was used (different points, so not identical sums).
  EXPECT_GT(largest, 0.0) << "no cell was integrated by the flat rule";
}

// Below distress at 545 and 136 rad/s (full film, load on film 2's contact).
INSTANTIATE_TEST_SUITE_P(PaperCase, FlatContactRule, ::testing::Values(Case{545.0, 100.0}, Case{136.0, 150.0}));

}  // namespace
}  // namespace twb
