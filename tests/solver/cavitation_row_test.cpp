// The steady solver's Newton writes the cavitation rows as min(p̂, ŵ), pseudo-time and
// everything else as Fischer–Burmeister (CavitationRow, bearing_model.h). The two rows
// vanish at the same states, so the switch may change how fast a state is reached, never
// which state: a state Newton converged with the minimum row must satisfy the
// Fischer–Burmeister rows to the tolerance, and the model must be left with its own row.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "solver/kinsol_newton.h"
#include "solver/natural_continuation.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

struct Case { double speed, load; };
class CavitationRowTest : public ::testing::TestWithParam<Case> {};

// The paper's bearing at `load`, reached by Newton from its steady state at 2 % less.
struct WarmStart {
  BearingModel model;
  SteadyReport report;
  std::vector<double> state;
  explicit WarmStart(const Case& c) : model(testing::table1_scene(true, true, true, true, c.speed, c.load)) {
    SteadySolver solver(model, {});
    model.set_load(0.98 * c.load);
    if (!solver.solve_cold(state).converged) throw std::runtime_error("no neighbouring state");
    model.set_load(c.load);
    report = solver.solve(state);
  }
};

TEST_P(CavitationRowTest, NewtonsStateSatisfiesTheFischerBurmeisterRows) {
  WarmStart w(GetParam());
  ASSERT_TRUE(w.report.converged) << w.report.message;
  ASSERT_EQ(w.report.strategy, "newton");
  EXPECT_EQ(w.model.cavitation_row(), CavitationRow::fischer_burmeister) << "the solver did not restore the row";

  // Newton met 1e-10/(2 + √2) in the minimum rows. The Fischer–Burmeister rows differ
  // only in the pressure rows, where |φ_FB(a, b)| ≤ (2 + √2)|min(a, b)| (Tseng), so the
  // state meets the tolerance 1e-10 in the model's own rows, as every later check of
  // it (arclength start, runaway, load-step march) expects.
  const NewtonSettings tolerance{};
  std::vector<double> r(w.state.size());
  w.model.evaluate(w.state, r, {});
  for (std::size_t k = 0; k < r.size(); ++k)
    EXPECT_LE(std::abs(r[k]), tolerance.residual_tolerance) << w.model.block_name(Index(k)) << ", row " << k;
}

TEST(NewtonFormScope, LeavesTheFormItFound) {
  // A solve inside an open scope (a caller already in Newton's form) must not switch
  // the model back to its own rows, and the scope must restore them when it closes.
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 500.0);
  testing::use_coarse_mesh(s);
  BearingModel m(s);
  SteadySolver solver(m, {});
  {
    const NewtonForm outer(m);
    std::vector<double> u;
    ASSERT_TRUE(solver.solve_cold(u).converged);
    m.set_load(510.0);
    ASSERT_TRUE(solver.solve(u).converged);
    EXPECT_EQ(m.cavitation_row(), CavitationRow::minimum);
  }
  EXPECT_EQ(m.cavitation_row(), CavitationRow::fischer_burmeister);
}

TEST_P(CavitationRowTest, NewtonFromTheNeighbourConvergesQuadratically) {
  // The first residual is the 2 % load imbalance, 0.0196 of the load. Once the
  // cavitated nodes are known the minimum row makes the system smooth, and Newton
  // squares the residual each step: 3.9e-4, 1.6e-7, 7e-14 at 100 N; on the hot branch
  // the first step overshoots (0.035), then 6.8e-6, 9e-13. Either way within the
  // tolerance in 3 iterations. With Fischer–Burmeister rows the hot-branch case (545 rad/s, 500 N)
  // needs a 4th: the nodes on the cavitation boundary slow its last steps to a
  // superlinear rate (3e-8 after the 3rd step).
  WarmStart w(GetParam());
  ASSERT_TRUE(w.report.converged) << w.report.message;
  EXPECT_LE(w.report.iterations, 3);
  EXPECT_EQ(w.report.jacobian_evaluations, w.report.iterations);
}

TEST_P(CavitationRowTest, ASweepCorrectsInNewtonsFormAndLeavesTheModelsOwn) {
  // Natural continuation corrects each 2 % step from the tangent's prediction, close
  // enough for Newton's form to converge quadratically: the residual after the
  // prediction is O(Δλ²), ~1e-4, then ~1e-8, ~1e-16, so at most 3 iterations a step.
  WarmStart w(GetParam());
  ASSERT_TRUE(w.report.converged) << w.report.message;
  NaturalSettings settings;
  settings.predictor = Predictor::tangent;
  const double load = w.model.load();
  const double step = 0.02 * load;
  settings.initial_step = settings.max_step = step;
  const NaturalReport rep = continue_in_parameter(w.model, w.state, w.model.parameter(), load + 5 * step, settings);
  ASSERT_TRUE(rep.reached_target) << rep.message;
  EXPECT_EQ(rep.accepted, 5);
  EXPECT_EQ(rep.rejected, 0) << rep.last_rejection;
  EXPECT_LE(rep.corrector_iterations, 3 * rep.accepted);
  EXPECT_EQ(w.model.cavitation_row(), CavitationRow::fischer_burmeister) << "the sweep did not restore the row";
}

// Below distress (full film, cavitated half) and on the hot branch at 545 rad/s; below
// distress at 136 rad/s.
INSTANTIATE_TEST_SUITE_P(PaperCase, CavitationRowTest,
                         ::testing::Values(Case{545.0, 100.0}, Case{545.0, 500.0}, Case{136.0, 500.0}));

}  // namespace
}  // namespace twb
