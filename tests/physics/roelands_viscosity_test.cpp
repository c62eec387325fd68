// Roelands viscosity, docs/physics.md section 5 / paper eq [17].
#include "physics/roelands_viscosity.h"

#include <cmath>

#include <gtest/gtest.h>

namespace {

const twb::RoelandsViscosity transmission_fluid{6.31e-5, 3.545, 1.053};

double kelvin(double celsius) { return celsius + 273.15; }

TEST(RoelandsViscosity, MatchesModelCheckValues) {
  // docs/physics.md section 5 quotes 4 significant digits: test to relative 1e-4.
  EXPECT_NEAR(transmission_fluid(kelvin(24.0)).value / 0.06081, 1.0, 1e-4);
  EXPECT_NEAR(transmission_fluid(kelvin(100.0)).value / 0.005992, 1.0, 1e-4);
}

TEST(RoelandsViscosity, MatchesIndependentHighPrecisionValues) {
  // Evaluated independently with mpmath at 30 digits.
  EXPECT_NEAR(transmission_fluid(kelvin(24.0)).value / 0.0608057845744168484, 1.0, 1e-13);
  EXPECT_NEAR(transmission_fluid(kelvin(-40.0)).value / 8.55778456250923359, 1.0, 1e-13);
  const auto at60 = transmission_fluid(kelvin(60.0));
  EXPECT_NEAR(at60.value / 0.0161024404358076133, 1.0, 1e-13);
  EXPECT_NEAR(at60.slope / -0.000481894979616627530, 1.0, 1e-12);  // mpmath diff
}

TEST(RoelandsViscosity, SlopeMatchesCentralDifferences) {
  // Central difference relative error ~ (k dT)^2/6 + eps/(k dT)... with k = |d ln mu/dT|
  // <= 1.1 /K over this range (steepest at -120 C, on the continuation). dT = 1e-4 K:
  // truncation <= 2e-9, roundoff ~1e-12, so 1e-7 relative is safe yet catches a wrong
  // slope. The points avoid the C1 (not C2) join at -100 C, where a difference
  // straddling it carries an O(dT) error instead.
  for (double celsius : {-120.0, -100.5, -99.5, -60.0, 0.0, 24.0, 60.0, 100.0, 150.0, 300.0}) {
    const double step = 1e-4;
    const double t = kelvin(celsius);
    const double fd = (transmission_fluid(t + step).value -
                       transmission_fluid(t - step).value) / (2 * step);
    EXPECT_NEAR(transmission_fluid(t).slope / fd, 1.0, 1e-7) << celsius;
  }
}

TEST(RoelandsViscosity, FinitePositiveMonotoneBelowTheFitRange) {
  // The fit's exponent diverges at T_C = -135; the kernel must stay usable there.
  double previous = 0.0;
  for (double celsius = 400.0; celsius >= -600.0; celsius -= 0.5) {
    const auto mu = transmission_fluid(kelvin(celsius));
    ASSERT_TRUE(std::isfinite(mu.value) && std::isfinite(mu.slope)) << celsius;
    ASSERT_GT(mu.value, previous) << celsius;  // viscosity rises as T falls
    ASSERT_LT(mu.slope, 0.0) << celsius;
    previous = mu.value;
  }
  // C1 at the continuation point.
  const double join = kelvin(twb::RoelandsViscosity::continuation_celsius);
  const auto below = transmission_fluid(join - 1e-9);
  const auto above = transmission_fluid(join + 1e-9);
  EXPECT_NEAR(below.value / above.value, 1.0, 1e-7);
  EXPECT_NEAR(below.slope / above.slope, 1.0, 1e-7);
}

}  // namespace
