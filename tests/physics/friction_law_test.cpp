// Empirical dry friction, docs/physics.md section 6 / paper eq [18].
#include "physics/friction_law.h"

#include <cmath>

#include <gtest/gtest.h>

namespace {

TEST(EmpiricalFriction, FollowsTheRegressionInsideItsRange) {
  // ln(1000) = 6.907755278982137: f = 0.48 - 0.3453877639491069.
  const auto f = twb::empirical_friction(1000.0);
  EXPECT_NEAR(f.coefficient, 0.1346122360508931, 1e-15);
  EXPECT_NEAR(f.slope, -0.05 / 1000.0, 1e-18);
  EXPECT_FALSE(f.clamped);
}

TEST(EmpiricalFriction, ClampsOutsideItsRange) {
  const auto low = twb::empirical_friction(10.0);
  EXPECT_TRUE(low.clamped);
  EXPECT_EQ(low.slope, 0.0);
  EXPECT_NEAR(low.coefficient, 0.48 - 0.05 * std::log(260.5), 1e-15);
  const auto zero = twb::empirical_friction(0.0);  // no contact: still finite
  EXPECT_TRUE(zero.clamped);
  EXPECT_EQ(zero.coefficient, low.coefficient);
  const auto high = twb::empirical_friction(5000.0);
  EXPECT_TRUE(high.clamped);
  EXPECT_EQ(high.slope, 0.0);
  EXPECT_NEAR(high.coefficient, 0.48 - 0.05 * std::log(1725.6), 1e-15);
  EXPECT_FALSE(twb::empirical_friction(260.5).clamped);
  EXPECT_FALSE(twb::empirical_friction(1725.6).clamped);
}

TEST(EmpiricalFriction, SlopeMatchesCentralDifferences) {
  // Step 1e-3 N on a log law at F >= 260 N: truncation ~ (1e-3/260)^2, tiny: 1e-8.
  for (double force : {300.0, 800.0, 1700.0}) {
    const double step = 1e-3;
    const double fd = (twb::empirical_friction(force + step).coefficient -
                       twb::empirical_friction(force - step).coefficient) / (2 * step);
    EXPECT_NEAR(twb::empirical_friction(force).slope / fd, 1.0, 1e-8);
  }
}

TEST(ConstantFriction, IsConstant) {
  const auto f = twb::constant_friction(0.12);
  EXPECT_EQ(f.coefficient, 0.12);
  EXPECT_EQ(f.slope, 0.0);
  EXPECT_FALSE(f.clamped);
}

}  // namespace
