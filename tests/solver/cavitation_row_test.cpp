// The steady solver's Newton writes the cavitation rows as min(p̂, ŵ), pseudo-time and
// everything else as Fischer–Burmeister (CavitationRow, bearing_model.h). The two rows
// vanish at the same states, so the switch may change how fast a state is reached, never
// which state: a state Newton converged with the minimum row must satisfy the
// Fischer–Burmeister rows to the tolerance, and the model must be left with its own row.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/table1_scene.h"
#include "twb/model/bearing_model.h"
#include "twb/solver/kinsol_newton.h"
#include "twb/solver/natural_continuation.h"
#include "twb/solver/steady_solver.h"

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

  // With the minimum row every residual is within the tolerance 1e-10. The
  // Fischer–Burmeister row differs only in the pressure rows, where
  // (2 − √2)|min(a, b)| ≤ |φ_FB(a, b)| ≤ (2 + √2)|min(a, b)| (Tseng's bounds), so it is
  // within (2 + √2)·1e-10 there and within 1e-10 everywhere else.
  const NewtonSettings tolerance{};
  std::vector<double> r(w.state.size());
  w.model.evaluate(w.state, r, {});
  for (const UnknownBlock& b : w.model.layout().blocks()) {
    const double bound = (b.effect == "hydrodynamics" ? 2.0 + std::sqrt(2.0) : 1.0) * tolerance.residual_tolerance;
    for (Index k = b.offset; k < b.offset + b.size; ++k)
      EXPECT_LE(std::abs(r[std::size_t(k)]), bound) << b.name << ", row " << k;
  }
}

TEST_P(CavitationRowTest, NewtonFromTheNeighbourConvergesQuadratically) {
  // The first residual is the 2 % load imbalance, 0.0196 of the load. Once the
  // cavitated nodes are known the minimum row makes the system smooth, and Newton
  // squares the residual each step: ~4e-4, ~2e-7, ~4e-14, within the tolerance 1e-10 in
  // 3 iterations. With Fischer–Burmeister rows the hot-branch case (545 rad/s, 500 N)
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
  const NaturalReport rep = continue_in_parameter(w.model, w.state, load + 5 * step, settings);
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
