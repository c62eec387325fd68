// A quantity an effect reports of its own (model/reported_quantity.h) goes from the
// effect's file to states.csv and the journal's bytes without a change of theirs: the
// worked example is support/prescribed_wear.h's deepest wear, an effect from outside the
// model; convection's heat carried is the registered one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "../support/prescribed_wear.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "model/convection_effect.h"
#include "model/reported_quantity.h"
#include "results/record_bytes.h"
#include "study/searches/steady_solver.h"
#include "twb/results/state_quantities.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"

namespace twb {
namespace {

Scene heated_washer() {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 300.0);
  testing::use_coarse_mesh(s);
  return s;
}

// The worn state's deepest wear comes back from describe(), in the table states.csv is
// written from (its last column: its effect is not a registered one), in trajectory.csv's
// and through the journal's bytes. The depth's row is linear in its own unknown alone (depth − d̂ = 0), so
// Newton holds it to rounding: the value is compared to 1e-12 of itself.
TEST(ReportedQuantity, AnEffectsOwnQuantityReachesStatesCsvAndTheJournal) {
  const Scene s = heated_washer();
  const double deepest = 0.4 * s.asperities.summit_sigma;
  // Deepest at θ = 0, a node of every mesh.
  BearingModel model(s, {testing::PrescribedWear::maker(
                            [deepest](double, double theta) { return deepest * 0.5 * (1.0 + std::cos(theta)); })});
  std::vector<double> u;
  ASSERT_TRUE(SteadySolver(model, {}).solve_cold(u).converged);
  SolvedState row;
  row.state = model.describe(u);
  const std::string column(testing::PrescribedWear::kReported[0].column);
  const std::optional<double> reported = row.state.reported_value(column);
  ASSERT_TRUE(reported.has_value());
  EXPECT_NEAR(*reported, deepest * 1e6, 1e-12 * deepest * 1e6);

  const ResultTable table = states_table({row}, {}, false);
  ASSERT_FALSE(table.columns().empty());
  const ResultColumn& last = table.columns().back();
  EXPECT_EQ(last.name, column);
  ASSERT_EQ(last.numbers.size(), 1u);
  EXPECT_EQ(last.numbers[0], *reported);

  TrajectorySample sample;
  sample.state = row.state;
  const ResultTable trajectory = trajectory_table({sample});
  const auto in_trajectory = std::find_if(trajectory.columns().begin(), trajectory.columns().end(),
                                          [&](const ResultColumn& c) { return c.name == column; });
  ASSERT_NE(in_trajectory, trajectory.columns().end());
  ASSERT_EQ(in_trajectory->numbers.size(), 1u);
  EXPECT_EQ(in_trajectory->numbers[0], *reported);

  RecordWriter out;
  out(row);
  SolvedState back;
  RecordReader in(out.bytes(), "a worn state");
  in(back);
  in.finish();
  EXPECT_EQ(back.state.reported_value(column), reported);
}

// A registered effect's quantities are state quantities (so `twb columns`, Python's column
// lists and the docs' table name them), written in states.csv and trajectory.csv only
// where the effect is on.
TEST(ReportedQuantity, ARegisteredEffectsQuantitiesAreStateQuantities) {
  const auto listed = effect_quantities();
  ASSERT_TRUE(std::any_of(listed.begin(), listed.end(),
                          [](const ReportedQuantity& q) { return q.column == ConvectionEffect::kHeatCarried; }));
  for (const ReportedQuantity& q : listed) {
    const StateQuantity& state = state_quantity(q.column);
    EXPECT_EQ(state.unit, q.unit);
    EXPECT_EQ(state.meaning, q.meaning);
    EXPECT_TRUE(state.where) << q.column << " is written only where some state has it";
  }
  Scene s = heated_washer();
  for (const bool convection : {false, true}) {
    s.effects.convection = convection;
    BearingModel model(s);
    std::vector<double> u;
    ASSERT_TRUE(SteadySolver(model, {}).solve_cold(u).converged);
    SolvedState row;
    row.state = model.describe(u);
    TrajectorySample sample;
    sample.state = row.state;
    for (const ResultTable& table : {states_table({row}, {}, false), trajectory_table({sample})}) {
      const bool written = std::any_of(table.columns().begin(), table.columns().end(), [](const ResultColumn& c) {
        return c.name == ConvectionEffect::kHeatCarried;
      });
      EXPECT_EQ(written, convection);
    }
  }
}

}  // namespace
}  // namespace twb
