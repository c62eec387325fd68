// The bearing as a SteadySystem: the load derivative of the residual and the
// capacities of the thermal transient (steady_system.h, bearing_dynamics.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"

namespace twb {
namespace {

// ∂F/∂W against a central difference in W. The residual is rational in W (rows
// divided by W), so the difference's truncation error is O((ε/W)²)·|F| ≈ 1e-12 at
// ε = 1e-3 W, and its rounding error 1e-16·|S|/ε·W ≈ 1e-13: agreement to 1e-9
// absolute leaves room and still catches a wrong sign or a missing row.
TEST(BearingDynamics, LoadDerivativeMatchesDifference) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 400.0);
  s.mesh.radial_nodes = 5;
  s.mesh.circumferential_nodes = 12;
  BearingModel m(s);
  std::vector<double> u = m.cold_start();
  for (std::size_t k = 0; k < u.size(); ++k) u[k] += 0.01 * double(k % 7);  // not a steady state
  const auto n = u.size();
  std::vector<double> d(n), rp(n), rm(n);
  m.parameter_derivative(u, d);
  const double w = m.load(), eps = 1e-3 * w;
  m.set_parameter(w + eps);
  m.evaluate(u, rp, {});
  m.set_parameter(w - eps);
  m.evaluate(u, rm, {});
  m.set_parameter(w);
  int nonzero = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double fd = (rp[k] - rm[k]) / (2 * eps);
    EXPECT_NEAR(d[k], fd, 1e-9) << "row " << k << " (" << m.block_name(Index(k)) << ")";
    nonzero += d[k] != 0.0;
  }
  EXPECT_EQ(nonzero, 4);  // only the rigid-body balances see the load
}

// With the gear's stop (docs/physics.md section 19) the rigid rows are divided by the
// scene's load, held, and the load enters the gear's row alone, through the stop's
// reaction R̂ = (F2 − W)/S inside φ(ŝ, R̂): ∂φ/∂W = −φ_b/S. A forward difference (the
// load may not go below zero) extrapolated, 2·D(ε/2) − D(ε), has truncation O(ε²·φ‴)
// ≈ 1e-8·|φ‴| at ε = 1e-4 S, and rounding 1e-16·|φ|/ε ≈ 1e-12: 1e-9 leaves room and
// catches a wrong sign or a missing row. Checked with the stop free, with it engaged (a
// play shorter than the films' gaps), and at a load of zero.
TEST(BearingDynamics, WithTheGearsStopTheLoadEntersTheGearsRowAlone) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 400.0);
  s.mesh.radial_nodes = 5;
  s.mesh.circumferential_nodes = 12;
  const BearingModel free_model(s);
  std::vector<double> u = free_model.cold_start();
  for (std::size_t k = 0; k < u.size(); ++k) u[k] += 0.01 * double(k % 7);  // not a steady state
  const UnknownBlock& rigid = free_model.layout().blocks().front();
  ASSERT_EQ(rigid.effect, BlockEffect::mechanics);
  // The films' gaps at the axis, c1 + c2 (m).
  const double gaps = (u[std::size_t(rigid.offset)] + u[std::size_t(rigid.offset + 3)]) * free_model.clearance_scale();
  for (const double play : {10.0 * gaps, 0.5 * gaps}) {
    for (const double load : {400.0, 0.0}) {
      s.gear.axial_play = play;
      BearingModel m(s);
      m.set_load(load);
      const auto n = u.size();
      std::vector<double> d(n), r0(n), rh(n), r1(n);
      m.parameter_derivative(u, d);
      const double eps = 1e-4 * s.operating.load;
      m.evaluate(u, r0, {});
      m.set_parameter(load + 0.5 * eps);
      m.evaluate(u, rh, {});
      m.set_parameter(load + eps);
      m.evaluate(u, r1, {});
      int nonzero = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const double fd = 2.0 * (rh[k] - r0[k]) / (0.5 * eps) - (r1[k] - r0[k]) / eps;
        EXPECT_NEAR(d[k], fd, 1e-9) << "play " << play << " m, load " << load << " N: row " << k << " ("
                                    << m.block_name(Index(k)) << ")";
        nonzero += d[k] != 0.0;
      }
      // Free, the gear's row is R̂ itself (slope 1/S); engaged, Fischer–Burmeister's φ_b
      // is below 1 but not 0.
      EXPECT_EQ(nonzero, 1) << "play " << play << " m, load " << load << " N";
      EXPECT_GT(d[std::size_t(rigid.offset + 3)], 0.0);
    }
  }
}

// Only component temperatures have a capacity. Each node's time constant C_k (s) is at
// most that of a plate losing heat only through its thickness, ρ c t²/K (6.1 s for the
// carrier), since the film and in-plane paths only add conductance (the row scale
// counts the thin film's conductance, so C_k is much smaller: the row's reference time).
TEST(BearingDynamics, CapacitiesOnComponentTemperaturesOnly) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 400.0);
  BearingModel m(s);
  const std::vector<double> c = m.capacities();
  ASSERT_EQ(Index(c.size()), m.size());
  for (const UnknownBlock& b : m.layout().blocks())
    for (Index k = b.offset; k < b.offset + b.size; ++k) {
      if (b.differential) EXPECT_GT(c[std::size_t(k)], 0.0) << b.name;
      else EXPECT_EQ(c[std::size_t(k)], 0.0) << b.name;
    }
  const Material& steel = s.carrier.material;
  const double bound = steel.density * steel.specific_heat * s.carrier.thickness * s.carrier.thickness /
                       steel.conductivity;
  for (const ComponentHeat& comp : m.components()) {
    if (comp.id != ComponentId::carrier) continue;
    for (int k = 0; k < comp.node_count(); ++k) EXPECT_LE(c[std::size_t(comp.offset + k)], bound);
  }
}

}  // namespace
}  // namespace twb
