// Blok's flash temperature (physics/flash_temperature.h) against the closed forms of a
// circular contact of radius a with a uniform heat flux q on a half-space: the stationary
// source (Pe → 0) and Jaeger's fast moving one (Pe → ∞), each computed here on its own.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/beta.hpp>

#include "physics/flash_temperature.h"

namespace twb {
namespace {

constexpr double pi = std::numbers::pi;

// The fits' constants are printed to three or four digits (1.22, 0.6575, 1.273), so a
// fit meets an exact limit to about 5e-4 of it; 1e-3 leaves room for that and no more.
constexpr double kFitDigits = 1e-3;

// Stationary: the rise at the centre of a uniformly heated disc is q·a/k, its mean over
// the disc 8/(3π)·q·a/k (Carslaw and Jaeger).
TEST(FlashTemperature, MeetsTheStationarySource) {
  EXPECT_NEAR(flash_maximum_factor(0.0), 1.0, kFitDigits);
  EXPECT_NEAR(flash_mean_factor(0.0), 8.0 / (3.0 * pi), kFitDigits * 8.0 / (3.0 * pi));
}

// Fast: each strip along the motion takes the heat as a semi-infinite solid for its
// transit time, θ(x) = (2q/k)·sqrt(κ·x/(π·V)) at x behind the leading edge. Its largest
// value is at the trailing edge of the centre line (x = 2a) and its mean over the disc is
// the integral below, done by quadrature; with Pe = V·a/(2κ) both go as (q·a/k)/sqrt(Pe),
// which the fits reach within (1 + c/Pe)^(-1/2) − 1 ≈ c/(2 Pe): 6e-5 at Pe = 1e4.
TEST(FlashTemperature, MeetsJaegersFastSource) {
  const double q = 1e9, a = 5e-6, k = 50.0, kappa = 1.4e-5;
  const double peclet = 1e4, speed = 2.0 * kappa * peclet / a;
  const auto strip_rise = [&](double x) { return 2.0 * q / k * std::sqrt(kappa * x / (pi * speed)); };
  const double maximum = strip_rise(2.0 * a);
  // Mean: (1/(π a²)) ∫ over y of ∫_0^L θ(x) dx, L = 2 sqrt(a² − y²) the chord.
  const auto chord_integral = [&](double y) {
    const double chord = 2.0 * std::sqrt(std::max(a * a - y * y, 0.0));
    return 2.0 / 3.0 * chord * strip_rise(chord);  // ∫_0^L c·sqrt(x) dx = (2/3) L·c·sqrt(L)
  };
  const double mean = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(chord_integral, -a, a, 15, 1e-12) /
                      (pi * a * a);
  const double unit = q * a / k;
  EXPECT_NEAR(flash_maximum_factor(peclet) * unit, maximum, kFitDigits * maximum);
  EXPECT_NEAR(flash_mean_factor(peclet) * unit, mean, kFitDigits * mean);
  // The same mean in closed form: (2/sqrt(2π))·(2/3)·2^(3/2)·B(1/2, 7/4)/π per sqrt(Pe).
  const double closed = 2.0 / std::sqrt(2.0 * pi) * (2.0 / 3.0) * std::pow(2.0, 1.5) * boost::math::beta(0.5, 1.75) /
                        pi / std::sqrt(peclet) * unit;
  EXPECT_NEAR(mean, closed, 1e-9 * closed);
}

// Two bodies share the heat so that their surfaces rise alike (Blok): two equal bodies
// at rest each take half, and the rise is half of one body's; a body that takes no heat
// (no conductivity) leaves all of it to the other.
TEST(FlashTemperature, SharesTheHeatAsBlokPostulated) {
  const double q = 2e8, a = 3e-6;
  const FlashBody steel{50.0, 1.4e-5, 0.0};
  const double alone = q * a / steel.conductivity * flash_maximum_factor(0.0);
  EXPECT_NEAR(flash_temperature_rise(q, a, steel, steel), 0.5 * alone, 1e-12 * alone);
  EXPECT_NEAR(flash_temperature_rise(q, a, steel, FlashBody{0.0, 1.0, 0.0}), alone, 1e-12 * alone);
  // A fast sweep over the second body draws more of the heat into it: the rise falls.
  FlashBody swept = steel;
  swept.speed = 10.0;
  EXPECT_LT(flash_temperature_rise(q, a, steel, swept), 0.5 * alone);
  EXPECT_EQ(flash_temperature_rise(0.0, a, steel, swept), 0.0);
}

}  // namespace
}  // namespace twb
