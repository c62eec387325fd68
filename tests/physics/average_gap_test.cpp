// Average gap, docs/physics.md section 3 / paper eq [6].
#include "physics/average_gap.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <gtest/gtest.h>

namespace {

constexpr double sigma = 0.728e-6;  // m, combined roughness of Table 1 surfaces

// The definition: integral over delta > -h of (h + delta) G(delta), G = N(0, sigma^2),
// integrated numerically (independent of the closed form). Substituting x = h + delta
// >= 0 gives int_0^inf x G(x - h) dx on a half line, for Boost's exp_sinh quadrature.
double average_gap_by_quadrature(double h) {
  const auto integrand = [h](double x) {
    const double z = (x - h) / sigma;
    return x * std::exp(-0.5 * z * z) / (sigma * std::sqrt(2.0 * std::numbers::pi));
  };
  // Split at the Gaussian's peak (if inside) so both pieces are well resolved.
  if (h > 0) {
    boost::math::quadrature::tanh_sinh<double> finite;
    boost::math::quadrature::exp_sinh<double> half_line;
    return finite.integrate(integrand, 0.0, h, 1e-15) +
           half_line.integrate(integrand, h, std::numeric_limits<double>::infinity(), 1e-15);
  }
  boost::math::quadrature::exp_sinh<double> half_line;
  return half_line.integrate(integrand, 0.0, std::numeric_limits<double>::infinity(), 1e-15);
}

TEST(AverageGap, MatchesQuadratureOfItsDefinition) {
  for (double H : {-5.0, -3.0, -1.0, -0.2, 0.0, 0.5, 1.0, 2.0, 3.0, 6.0}) {
    const double h = H * sigma;
    const double exact = average_gap_by_quadrature(h);
    EXPECT_NEAR(twb::average_gap(h, sigma).value / exact, 1.0, 1e-12) << "H = " << H;
  }
}

TEST(AverageGap, MatchesIndependentHighPrecisionValues) {
  // h_T/sigma from mpmath quadrature of the definition, 30 digits.
  const auto relative_to = [](double H, double reference_over_sigma) {
    return twb::average_gap(H * sigma, sigma).value / (reference_over_sigma * sigma);
  };
  EXPECT_NEAR(relative_to(-3.0, 0.000382154317047723596), 1.0, 1e-12);
  EXPECT_NEAR(relative_to(0.0, 0.398942280401432678), 1.0, 1e-14);
  EXPECT_NEAR(relative_to(0.5, 0.697796557401306030), 1.0, 1e-14);
}

TEST(AverageGap, SlopeIsOpenedFractionAndMatchesCentralDifferences) {
  // Step 1e-4 sigma: truncation ~ (1e-4)^2 relative, roundoff ~1e-12: bound 1e-7.
  for (double H : {-4.0, -1.0, 0.0, 0.8, 2.5, 5.0}) {
    const double h = H * sigma, step = 1e-4 * sigma;
    const double fd = (twb::average_gap(h + step, sigma).value -
                       twb::average_gap(h - step, sigma).value) / (2 * step);
    const double slope = twb::average_gap(h, sigma).slope;
    EXPECT_NEAR(slope, fd, 1e-7 * fd) << "H = " << H;
    EXPECT_NEAR(slope, 0.5 * (1 + std::erf(H / std::numbers::sqrt2)), 1e-15);
  }
}

TEST(AverageGap, AlwaysPositiveAndEqualsGapWhenOpen) {
  for (double H = -8.0; H <= 20.0; H += 0.01) {
    const double h = H * sigma;
    const double gap = twb::average_gap(h, sigma).value;
    ASSERT_GT(gap, 0.0) << "H = " << H;
    ASSERT_GE(gap, h) << "H = " << H;  // (h + delta) > h over the wetted part
    if (H >= 3.0) {
      ASSERT_LT((gap - h) / h, 1.3e-4) << "H = " << H;
    }
  }
}

// The closed form evaluated in full, as average_gap does below its open threshold.
twb::ValueSlope closed_form(double h) {
  const double scaled = h / (sigma * std::numbers::sqrt2);
  const double gaussian = sigma * std::exp(-scaled * scaled) / std::sqrt(2.0 * std::numbers::pi);
  const double closed = 0.5 * std::erfc(scaled);
  return {h + (gaussian - h * closed), 1.0 - closed};
}

TEST(AverageGap, OpenShortcutIsTheClosedFormToTheLastBit) {
  // Above the threshold average_gap skips exp and erfc; the full closed form must round
  // to the very same doubles there, from the threshold itself to far open.
  const double first = twb::exact_open_threshold * std::numbers::sqrt2 * sigma;
  int checked = 0;
  for (double h = first; h < 80.0 * sigma; h = std::nextafter(h * (1.0 + 1e-4), INFINITY)) {
    const twb::ValueSlope full = closed_form(h), fast = twb::average_gap(h, sigma);
    ASSERT_EQ(fast.value, full.value) << "h/sigma = " << h / sigma;
    ASSERT_EQ(fast.slope, full.slope) << "h/sigma = " << h / sigma;
    ++checked;
  }
  EXPECT_GT(checked, 20000);
  // Just below it the closed form still differs from {h, 1}: the threshold is not far
  // below where the shortcut would start to change results.
  const double below = 5.0 * std::numbers::sqrt2 * sigma;
  EXPECT_NE(closed_form(below).slope, 1.0);
}

}  // namespace

namespace twb {
namespace {

// ∂h_T/∂σ against central differences in σ (step 1e-6 σ: truncation O(step²) ~1e-12,
// rounding ε·h_T/step ~ 1e-10 of σ's scale), across contact and the open film.
TEST(AverageGapBySigma, IsTheSlopeInTheRoughness) {
  const double sigma = 0.7e-6, step = 1e-6 * sigma;
  for (const double x : {-3.0, -1.0, 0.0, 0.5, 2.0, 4.0}) {
    const double h = x * sigma;
    const double by_diff = (average_gap(h, sigma + step).value - average_gap(h, sigma - step).value) / (2.0 * step);
    EXPECT_NEAR(average_gap_by_sigma(h, sigma), by_diff, 1e-8) << x;
  }
}

// ∂(∂h_T/∂h)/∂σ the same way: the slope is O(1), so rounding is ε/step ~ 2e-10 of 1/σ.
TEST(AverageGapBySigma, IsTheSlopesSlopeInTheRoughness) {
  const double sigma = 0.7e-6, step = 1e-6 * sigma;
  for (const double x : {-3.0, -1.0, 0.0, 0.5, 2.0, 4.0}) {
    const double h = x * sigma;
    const double by_diff = (average_gap(h, sigma + step).slope - average_gap(h, sigma - step).slope) / (2.0 * step);
    EXPECT_NEAR(average_gap_slope_by_sigma(h, sigma) * sigma, by_diff * sigma, 1e-8) << x;
  }
}

}  // namespace
}  // namespace twb
