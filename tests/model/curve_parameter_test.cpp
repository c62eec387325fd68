// BearingModel::set_curve_parameter (the fold curve's second parameter) changes the
// bearing as a scene with that value would, keeping only the unknowns' scales: the
// steady state solved after the change is the state of a model built from the changed
// scene. Solved to the residual tolerance 1e-10 from the same cold start, the two agree
// in every reported quantity to ~1e-9 relative; 1e-7 leaves the conditioning its room.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "../support/table1_scene.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

BearingState solved(BearingModel& model) {
  SteadySolver solver(model, NewtonSettings{});
  std::vector<double> u;
  const SteadyReport rep = solver.solve_cold(u);
  if (!rep.converged) throw std::runtime_error("no steady state: " + rep.message);
  return model.describe(u);
}

struct Case {
  const char* name;
  CurveParameter parameter;
  double value;
  std::function<void(Scene&)> same_in_scene;
};

class CurveParameterTest : public ::testing::TestWithParam<Case> {};

TEST_P(CurveParameterTest, SetterMatchesARebuiltScene) {
  const Case& c = GetParam();
  Scene scene = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  scene.friction.law = FrictionLaw::constant;
  scene.friction.coefficient = 0.2;
  testing::use_coarse_mesh(scene);
  BearingModel changed(scene);
  changed.set_curve_parameter(c.parameter, c.value);
  EXPECT_EQ(changed.curve_parameter(c.parameter), c.value);
  Scene other = scene;
  c.same_in_scene(other);
  BearingModel rebuilt(other);
  const BearingState a = solved(changed), b = solved(rebuilt);
  for (const auto& [name, x, y] : {std::tuple{"T_mean", a.washer_mean_temperature, b.washer_mean_temperature},
                                   std::tuple{"hmin/sigma", a.hmin_over_sigma, b.hmin_over_sigma},
                                   std::tuple{"f_eff", a.f_eff, b.f_eff},
                                   std::tuple{"fluid share", a.fluid_share, b.fluid_share},
                                   std::tuple{"torque", a.torque, b.torque}})
    EXPECT_NEAR(x, y, 1e-7 * std::abs(y)) << c.name << ": " << name;
  // And it did change something: the value is not the scene's own.
  BearingModel original(scene);
  EXPECT_GT(std::abs(solved(original).washer_mean_temperature - a.washer_mean_temperature), 1e-3) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    Bearing, CurveParameterTest,
    ::testing::Values(Case{"speed", CurveParameter::speed, 953.0, [](Scene& s) { s.operating.speed = 953.0; }},
                      Case{"friction_coefficient", CurveParameter::friction_coefficient, 0.4,
                           [](Scene& s) { s.friction.coefficient = 0.4; }},
                      Case{"gear_tilt", CurveParameter::gear_tilt, 1.5e-3, [](Scene& s) { s.gear.tilt = 1.5e-3; }},
                      Case{"ambient_temperature", CurveParameter::ambient_temperature, 333.15,
                           [](Scene& s) { s.operating.ambient = 333.15; }},
                      Case{"viscosity_scale", CurveParameter::viscosity_scale, 1.7,
                           [](Scene& s) { s.lubricant.mu_infinity *= 1.7; }},
                      Case{"roughness", CurveParameter::roughness, 0.5e-6,
                           [](Scene& s) { set_roughness(s, 0.5e-6); }}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace twb
