// A load step's consistent start (load_step_march.h): the film and the rigid body at the
// new load with the old temperatures. From the bronze washer's film at 200 N, IDACalcIC
// alone does not reach 300 N (it failed there and the transient study exited 0); walked in
// load pieces it does, and the step then settles.
#include <gtest/gtest.h>

#include <string>

#include "solver/ida_transient.h"
#include "study/searches/steady_solver.h"
#include "study/searches/load_step_march.h"
#include "study/study_support.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

TEST(LoadStepStart, ALargeStepOnTheBronzeWasherStartsAndSettles) {
  const Scene scene = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/washers/bronze_cusn8.yaml",
                                 {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24"});
  BearingModel model(scene);
  model.set_load(200.0);
  const NewtonSettings newton = newton_settings(scene);
  std::vector<double> u;
  ASSERT_TRUE(SteadySolver(model, newton).solve_cold(u).converged);
  const StepMarch march = march_load_step(model, u, 200.0, 300.0, TransientSettings{}, newton, 0.0);
  EXPECT_TRUE(march.started) << march.message;
  EXPECT_TRUE(march.settled) << march.message;
  EXPECT_EQ(model.load(), 200.0);  // given back as it was
}

}  // namespace
}  // namespace twb
