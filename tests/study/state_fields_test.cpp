// Studies record the fields of every state they solve exactly when the scene asks for
// them (output.fields), whichever place records the state: the point study, and the
// distress search behind a load sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/table1_scene.h"
#include "study/study_runner.h"

namespace twb {
namespace {

Scene coarse(bool fields) {
  Scene s = testing::table1_scene(true, true, true, false, 545.0, 150.0);
  testing::use_coarse_mesh(s);
  s.output.fields = fields;
  return s;
}

TEST(StateFields, PointStudyRecordsFieldsOnlyOnRequest) {
  for (bool fields : {false, true}) {
    BearingModel model(coarse(fields));
    const StudyOutcome out = run_study(model, {});
    ASSERT_EQ(out.states.size(), 1u) << out.message;
    EXPECT_EQ(out.states[0].fields.size(), fields ? 2u : 0u);
  }
}

// Isothermal, so the sweep is continuation only (no transient): quick.
TEST(StateFields, LoadSweepRecordsFieldsOfEveryState) {
  Scene s = coarse(true);
  LoadSweepSettings sweep;
  sweep.grid.loads = {100.0, 200.0};
  sweep.grid.load_steps = 3;
  s.study.settings = sweep;
  BearingModel model(s);
  const StudyOutcome out = run_study(model, {});
  ASSERT_GE(out.states.size(), 3u) << out.message;
  for (const SolvedState& row : out.states) {
    ASSERT_EQ(row.fields.size(), 2u);
    // The fields are those of the state's own position: the plane's minimum.
    const FilmFields& f = row.fields[0];
    double smallest = f.gap[0];
    for (double h : f.gap) smallest = std::min(smallest, h);
    const double hmin = row.state.hmin_over_sigma * model.films()[0].sigma;
    EXPECT_GE(smallest, hmin - 1e-15);
    EXPECT_LE(smallest, hmin + (row.state.position.c1 - hmin) * (1 - std::cos(0.5 * f.mesh.dtheta())) + 1e-15);
  }
}

}  // namespace
}  // namespace twb
