// Patir & Cheng flow factors, docs/physics.md section 3 / paper eqs [2]-[5].
#include "physics/flow_factors.h"

#include <cmath>

#include <gtest/gtest.h>

namespace {

// Central difference with step 1e-5 on functions varying on an O(1) scale in H:
// truncation ~ f''' 1e-10/6, roundoff ~ 1e-16/1e-5 = 1e-11 (relative), so 1e-7 relative
// (plus a tiny absolute floor for near-zero slopes) is safe and still tight.
template <class F>
void expect_slope_matches_central_difference(F kernel, double H) {
  const double step = 1e-5;
  const double fd = (kernel(H + step).value - kernel(H - step).value) / (2 * step);
  const double slope = kernel(H).slope;
  EXPECT_NEAR(slope, fd, 1e-7 * std::abs(fd) + 1e-12) << "H = " << H;
}

TEST(PressureFlowFactor, ValuesFromTheFormula) {
  // phi(0) = 1 - 0.9 = 0.1; phi -> 1 at large H; independent hand values.
  EXPECT_DOUBLE_EQ(twb::pressure_flow_factor(0.0).value, 0.1);
  EXPECT_NEAR(twb::pressure_flow_factor(3.0).value, 1.0 - 0.9 * 0.18637397603940997, 1e-15);
  EXPECT_NEAR(twb::pressure_flow_factor(50.0).value, 1.0, 1e-12);
  EXPECT_TRUE(std::isfinite(twb::pressure_flow_factor(-10.0).value));  // H <= 0 allowed
}

TEST(PressureFlowFactor, SlopeMatchesCentralDifferences) {
  for (double H : {-3.0, -0.5, 0.0, 0.7, 2.0, 5.0, 9.0})
    expect_slope_matches_central_difference(twb::pressure_flow_factor, H);
}

TEST(ShearFlowFactor, BranchesMeetAtFiveAsModelStates) {
  const double below = twb::shear_flow_factor_Phi_s(5.0).value;
  const double above = twb::shear_flow_factor_Phi_s(std::nextafter(5.0, 10.0)).value;
  // Independent: 1.899 5^0.98 e^-3.35 = 0.3225737734624399 and 1.126 e^-1.25 =
  // 0.3226044012645740 (mpmath); they differ by 9.5e-5 relative.
  EXPECT_NEAR(below, 0.3225737734624399, 1e-14);
  EXPECT_NEAR(above, 0.3226044012645740, 1e-14);
  EXPECT_LT(std::abs(above - below) / above, 1e-4);
}

TEST(ShearFlowFactor, ClosedGapHasNoShearFlow) {
  EXPECT_EQ(twb::shear_flow_factor_Phi_s(0.0).value, 0.0);
  EXPECT_EQ(twb::shear_flow_factor_Phi_s(-2.0).value, 0.0);
  EXPECT_EQ(twb::shear_flow_factor_Phi_s(-2.0).slope, 0.0);
  // Continuous from above: 1.899 H^0.98 -> 0.
  EXPECT_LT(twb::shear_flow_factor_Phi_s(1e-12).value, 1e-10);
}

TEST(ShearFlowFactor, SlopeMatchesCentralDifferences) {
  for (double H : {0.01, 0.3, 1.0, 2.5, 4.9, 5.1, 8.0, 20.0})
    expect_slope_matches_central_difference(twb::shear_flow_factor_Phi_s, H);
}

TEST(ShearFlowFactor, WeightFollowsRoughnessShares) {
  EXPECT_EQ(twb::shear_flow_factor_weight(0.515e-6, 0.515e-6), 0.0);  // Table 1: phi_s = 0
  EXPECT_DOUBLE_EQ(twb::shear_flow_factor_weight(3.0, 4.0), (9.0 - 16.0) / 25.0);
  EXPECT_DOUBLE_EQ(twb::shear_flow_factor_weight(1.0, 0.0), 1.0);
  EXPECT_EQ(twb::shear_flow_factor_weight(0.0, 0.0), 0.0);
}

}  // namespace
