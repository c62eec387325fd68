// The carrier's temperature field as a modelling choice (docs/physics.md section 7): fixed in
// the load frame, T(r, θ), or circumferentially averaged, T(r). The averaged carrier
// allocates one unknown per ring, its state keeps every balance of a converged state,
// and it spreads film 1's hot spot over the ring, so its hottest node is cooler.
#include <gtest/gtest.h>

#include <algorithm>

#include "../support/converged_balances.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

Scene paper_case(CarrierTemperature carrier) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  testing::use_coarse_mesh(s);
  s.effects.carrier_temperature = carrier;
  return s;
}

const UnknownBlock& carrier_block(const BearingModel& m) {
  for (const UnknownBlock& b : m.layout().blocks())
    if (b.name.rfind("carrier temperature", 0) == 0) return b;
  throw std::logic_error("no carrier temperature block");
}

TEST(CarrierTemperature, AveragedCarrierHasOneUnknownPerRing) {
  const BearingModel fixed(paper_case(CarrierTemperature::load_frame));
  const BearingModel averaged(paper_case(CarrierTemperature::axisymmetric));
  EXPECT_EQ(carrier_block(fixed).size, 5 * 24);
  EXPECT_EQ(carrier_block(averaged).size, 5);
  EXPECT_EQ(fixed.size() - averaged.size(), 5 * 24 - 5) << "nothing else changes";
}

TEST(CarrierTemperature, AveragedCarrierKeepsTheBalancesAndSpreadsTheHotSpot) {
  double hottest[2];
  for (CarrierTemperature c : {CarrierTemperature::load_frame, CarrierTemperature::axisymmetric}) {
    BearingModel m(paper_case(c));
    SteadySolver solver(m, {});
    std::vector<double> u;
    const SteadyReport rep = solver.solve_cold(u);
    ASSERT_TRUE(rep.converged) << rep.message;
    const BearingState s = m.describe(u);
    testing::expect_balanced(s);
    const UnknownBlock& b = carrier_block(m);
    hottest[int(c)] = *std::max_element(u.begin() + b.offset, u.begin() + b.offset + b.size);
  }
  EXPECT_LT(hottest[1], hottest[0]) << "averaging over the ring must lower the carrier's peak";
}

}  // namespace
}  // namespace twb
