// A converged state of the paper's bearing satisfies what a converged state promises
// (issue contract): force and moment balance to 1e-8 of the load, the energy balance
// to 1e-8 of the heat generated, and the cavitation complementarity. The solver's
// tolerance is 1e-10 on the scaled residual (forces over the load, heat rows in kelvin
// over a node conductance), which bounds the balances well inside 1e-8.
#include <gtest/gtest.h>

#include "../support/converged_balances.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

struct Case { double speed, load; };
class ConvergedState : public ::testing::TestWithParam<Case> {};

TEST_P(ConvergedState, SatisfiesBalancesAndComplementarity) {
  const Case c = GetParam();
  BearingModel m(testing::table1_scene(true, true, true, true, c.speed, c.load));
  SteadySolver solver(m, {});
  std::vector<double> u;
  const SteadyReport rep = solver.solve_cold(u);
  ASSERT_TRUE(rep.converged) << rep.message;
  const BearingState s = m.describe(u);
  testing::expect_balanced(s);
  EXPECT_LT(s.complementarity_error, 1e-8);
  EXPECT_GT(s.heat_generated, 0.0);
  EXPECT_NEAR(s.fluid_share + s.contact_share, 1.0, 1e-8) << "the sliding film carries the whole load";
  // Pressures are non-negative (Reynolds condition).
  const Film& f = m.films()[0];
  for (int i = 0; i < f.mesh.radial_nodes(); ++i)
    for (int j = 0; j < f.mesh.circumferential_nodes(); ++j) EXPECT_GE(m.pressure_at(u, f, i, j), -1e-6 * m.pressure_scale());
}

INSTANTIATE_TEST_SUITE_P(PaperCase, ConvergedState,
                         ::testing::Values(Case{136.0, 1000.0}, Case{545.0, 150.0}, Case{545.0, 500.0},
                                           Case{953.0, 1500.0}));

}  // namespace
}  // namespace twb
