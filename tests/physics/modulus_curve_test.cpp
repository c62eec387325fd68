// A modulus against temperature (docs/physics.md section 23, [M1]).
#include "physics/modulus_curve.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace twb {
namespace {

// Unfilled PEEK's points (docs/materials.md): a fall of an order of magnitude through
// its glass transition, the case a spline would ring at.
const std::vector<double> kPeekT{296.15, 373.15, 413.15, 423.15, 433.15, 473.15, 523.15};
const std::vector<double> kPeekE{3.7e9, 3.4e9, 3.0e9, 1.5e9, 0.6e9, 0.45e9, 0.35e9};

TEST(ModulusCurve, PassesThroughTheDataAndFallsMonotonicallyBetween) {
  const ModulusCurve curve(kPeekT, kPeekE);
  for (std::size_t k = 0; k < kPeekT.size(); ++k)
    EXPECT_NEAR(curve.at(kPeekT[k]).modulus, kPeekE[k], 1e-12 * kPeekE[k]);  // exp(log(E)): rounding only
  double previous = curve.at(kPeekT.front()).modulus;
  for (double t = kPeekT.front(); t <= kPeekT.back(); t += 0.05) {
    const ModulusCurve::Value v = curve.at(t);
    EXPECT_LE(v.modulus, previous * (1 + 1e-14)) << t;
    EXPECT_LE(v.slope, 0.0) << t;
    EXPECT_EQ(v.range, ModulusCurve::Value::Range::inside);
    previous = v.modulus;
  }
}

// The slope is the curve's own: against a central difference of step h, whose error is
// O(h²·E''') (the pieces are cubics in ln E): at h = 1e-3 K and E''' of order
// E/(10 K)³, a relative error of order 1e-8; rounding adds about 1e-16·E/h, 1e-13 of E.
TEST(ModulusCurve, ItsSlopeIsTheDerivativeOfItsValue) {
  const ModulusCurve curve(kPeekT, kPeekE);
  const double h = 1e-3;
  for (double t : {300.0, 380.0, 418.0, 428.0, 440.0, 500.0}) {
    const double difference = (curve.at(t + h).modulus - curve.at(t - h).modulus) / (2 * h);
    EXPECT_NEAR(curve.at(t).slope, difference, 1e-6 * curve.at(t).modulus) << t;
  }
}

TEST(ModulusCurve, OutsideItsDataItHoldsTheNearerEndAndSaysWhere) {
  const ModulusCurve curve(kPeekT, kPeekE);
  const ModulusCurve::Value cold = curve.at(250.0), hot = curve.at(600.0);
  EXPECT_DOUBLE_EQ(cold.modulus, kPeekE.front());
  EXPECT_DOUBLE_EQ(hot.modulus, kPeekE.back());
  EXPECT_EQ(cold.slope, 0.0);
  EXPECT_EQ(hot.slope, 0.0);
  EXPECT_EQ(cold.range, ModulusCurve::Value::Range::below);
  EXPECT_EQ(hot.range, ModulusCurve::Value::Range::above);
  EXPECT_EQ(curve.highest_temperature(), kPeekT.back());
}

// Two points: the straight line in ln E (PCHIP's slopes are then the secant), so the
// midpoint's modulus is the ends' geometric mean. Three: monotone through the middle.
TEST(ModulusCurve, TwoOrThreePointsAreMonotoneToo) {
  const std::vector<double> t2{300.0, 400.0}, e2{4e9, 1e9};
  EXPECT_NEAR(ModulusCurve(t2, e2).at(350.0).modulus, 2e9, 1e-12 * 2e9);
  const std::vector<double> t3{300.0, 400.0, 410.0}, e3{4e9, 3e9, 0.5e9};
  const ModulusCurve three(t3, e3);
  EXPECT_NEAR(three.at(400.0).modulus, 3e9, 1e-12 * 3e9);
  for (double t = 300.0; t < 410.0; t += 0.1) EXPECT_GE(three.at(t).modulus, three.at(t + 0.1).modulus) << t;
  const std::vector<double> t1{300.0}, e1{5e9};
  EXPECT_DOUBLE_EQ(ModulusCurve(t1, e1).at(450.0).modulus, 5e9);
  // A constant modulus has no data to leave (physics §23's criterion must not fire on it).
  EXPECT_EQ(ModulusCurve(t1, e1).at(450.0).range, ModulusCurve::Value::Range::inside);
}

TEST(ModulusCurve, RefusesDataThatAreNotACurve) {
  const std::vector<double> falling{400.0, 300.0}, rising{300.0, 400.0}, e{1e9, 2e9}, zero{1e9, 0.0}, one{1e9};
  EXPECT_THROW(ModulusCurve(falling, e), std::invalid_argument);
  EXPECT_THROW(ModulusCurve(rising, zero), std::invalid_argument);
  EXPECT_THROW(ModulusCurve(rising, one), std::invalid_argument);
  EXPECT_THROW(ModulusCurve(std::vector<double>{}, std::vector<double>{}), std::invalid_argument);
  EXPECT_THROW(ModulusCurve(kPeekT, kPeekE).at(std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace twb
