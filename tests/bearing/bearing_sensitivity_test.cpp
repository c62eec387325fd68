// twb::Bearing::sensitivity: the last state's derivatives at the Bearing's own operating
// point (a load and speed that are not the scene's), against centred differences of whole
// solves at p ± Δ, Δ = 1e-3·|p|, for the speed, the load and a geometry input. The
// allowance, as in tests/study/sensitivity_test.cpp: twice the difference's truncation
// measured against 2Δ, plus the whole solves' tolerance over the step.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "twb/bearing.h"
#include "twb/scene/scene_inputs.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

Scene coarse_paper() {
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                    {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "solver.residual_tolerance=1e-12"});
}

// The state's quantities at (load, speed) with the input at `path` set to value (or the
// scene's where path is the load or speed, given as the point).
std::vector<std::pair<std::string, double>> quantities(const Scene& scene, const std::string& path, double value,
                                                       double load, double speed) {
  Scene s = scene;
  if (path == "operating.load") load = value;
  else if (path == "operating.speed") speed = value;
  else {
    const std::pair<std::string, double> set[] = {{path, value}};
    s = with_inputs(scene, set);
  }
  const SolvedState st = Bearing(s).solve(load, speed);
  return {{"torque_Nm", st.state.torque}, {"f_eff", st.state.f_eff},
          {"T_mean_C", st.state.washer_mean_temperature}, {"T_max_C", st.state.max_film_temperature},
          {"hmin_over_sigma", st.state.hmin_over_sigma}, {"fluid_share", st.state.fluid_share}};
}

TEST(BearingSensitivity, TheLastStateAtItsOwnPointMovesAsWholeSolvesDo) {
  const Scene scene = coarse_paper();
  const double load = 120.0, speed = 400.0;  // the scene's are 500 N, 545 rad/s
  Bearing bearing(scene);
  EXPECT_THROW(bearing.sensitivity("operating.speed"), std::logic_error);
  bearing.solve(load, speed);
  for (const std::string path : {"operating.speed", "operating.load", "geometry.washer.outer_diameter"}) {
    const double p = path == "operating.speed" ? speed : path == "operating.load" ? load : scene_input(scene, path).value;
    const double delta = 1e-3 * p;
    const auto d = bearing.sensitivity(path);
    const auto m2 = quantities(scene, path, p - 2 * delta, load, speed), m1 = quantities(scene, path, p - delta, load, speed),
               p1 = quantities(scene, path, p + delta, load, speed), p2 = quantities(scene, path, p + 2 * delta, load, speed);
    ASSERT_EQ(d.size(), m1.size());
    for (std::size_t k = 0; k < d.size(); ++k) {
      EXPECT_EQ(d[k].first, m1[k].first);
      const double fd1 = (p1[k].second - m1[k].second) / (2 * delta), fd2 = (p2[k].second - m2[k].second) / (4 * delta);
      const double tolerance = 2 * std::abs(fd2 - fd1) + 1e-6 * std::abs(m1[k].second / p);
      EXPECT_NEAR(d[k].second, fd1, tolerance) << d[k].first << " / " << path;
    }
  }
  EXPECT_THROW(bearing.sensitivity("geometry.gear.tilted"), std::invalid_argument);
}

}  // namespace
}  // namespace twb
