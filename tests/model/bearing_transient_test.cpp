// The bearing's pseudo-time thermal transient (docs/physics.md sections 7-8) against its
// steady states: with no load change it stays put; after a small stable load step it
// converges to the state KINSOL finds at the new load (issue: to 1e-8 relative).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/state_difference.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "solver/ida_transient.h"
#include "solver/relaxation_time.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

// 5×24 nodes at 545 rad/s: the cool branch folds near 160 N on this mesh; 120 N is
// well below it.
Scene coarse_scene() {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 120.0);
  testing::use_coarse_mesh(s);
  return s;
}

TransientSettings tight_tolerances() {
  TransientSettings t;
  t.relative_tolerance = 1e-11;
  t.absolute_tolerance = 1e-13;
  return t;
}

// IDA's tolerances are set 1e-11 relative (1e-13 absolute) so that its own error stays
// below the 1e-8 the test asks. On a steady state the transient's rate is the residual,
// 1e-10 at most: over 60 relaxation times that moves the state by no more than the
// Newton tolerance's worth of the steady state's sensitivity.
TEST(BearingTransient, SteadyStateWithoutLoadChangeStaysPut) {
  BearingModel m(coarse_scene());
  SteadySolver steady(m, NewtonSettings{});
  std::vector<double> u;
  ASSERT_TRUE(steady.solve_cold(u).converged);
  const double tau = slowest_relaxation_time(m, u, 20);
  IdaTransient ida(m, tight_tolerances());
  ASSERT_TRUE(ida.start(0.0, u).ok);
  const TransientStatus st = ida.advance(60 * tau);
  ASSERT_TRUE(st.ok) << st.message;
  EXPECT_LT(testing::relative_difference(ida.state(), u), 1e-8);
}

// A 3 % load step: after 60 slowest relaxation times (e^−60 of the initial offset
// remains) the trajectory sits on the new steady state to IDA's tolerance.
TEST(BearingTransient, SmallLoadStepConvergesToTheNewtonState) {
  BearingModel m(coarse_scene());
  SteadySolver steady(m, NewtonSettings{});
  std::vector<double> u;
  ASSERT_TRUE(steady.solve_cold(u).converged);
  const double tau = slowest_relaxation_time(m, u, 20);
  m.set_load(1.03 * m.load());
  std::vector<double> target = u;
  ASSERT_TRUE(steady.solve(target).converged);
  IdaTransient ida(m, tight_tolerances());
  ASSERT_TRUE(ida.start(0.0, u).ok);
  EXPECT_GT(testing::relative_difference(ida.state(), target), 1e-4);  // the step does move the state
  const TransientStatus st = ida.advance(60 * tau);
  ASSERT_TRUE(st.ok) << st.message;
  EXPECT_LT(testing::relative_difference(ida.state(), target), 1e-8);
}

}  // namespace
}  // namespace twb
