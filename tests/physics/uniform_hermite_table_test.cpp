// Uniform cubic Hermite interpolation (the contact table's evaluator).
#include "physics/uniform_hermite_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include "twb/error_family.h"

namespace {

// A cubic is reproduced exactly by cubic Hermite interpolation from exact nodal slopes.
double cubic(double x) { return 0.5 - 2.0 * x + 0.75 * x * x - 0.125 * x * x * x; }
double cubic_slope(double x) { return -2.0 + 1.5 * x - 0.375 * x * x; }

twb::UniformHermiteTable tabulate(double (*f)(double), double (*df)(double), double x0,
                                  double dx, int nodes) {
  std::vector<double> values, slopes;
  for (int i = 0; i < nodes; ++i) {
    values.push_back(f(x0 + dx * i));
    slopes.push_back(df(x0 + dx * i));
  }
  return {x0, dx, values, slopes};
}

TEST(UniformHermiteTable, ReproducesCubicsAndTheirSlopes) {
  const auto table = tabulate(cubic, cubic_slope, -1.0, 0.3, 11);
  for (double x = -1.0; x <= table.x_last(); x += 0.0137) {
    const auto v = table.evaluate(x);
    EXPECT_NEAR(v.value, cubic(x), 1e-13) << x;
    EXPECT_NEAR(v.slope, cubic_slope(x), 1e-12) << x;
  }
  EXPECT_NEAR(table.evaluate(table.x_last()).value, cubic(table.x_last()), 1e-13);
}

TEST(UniformHermiteTable, InterpolatesNodesAndIsFourthOrder) {
  // Error at fixed points must drop ~16x when the spacing halves (h^4 convergence).
  const auto f = [](double x) { return std::sin(x); };
  double previous_error = 0.0;
  for (int nodes : {11, 21, 41}) {
    const double dx = 2.0 / (nodes - 1);
    const auto table = tabulate([](double x) { return std::sin(x); },
                                [](double x) { return std::cos(x); }, 0.0, dx, nodes);
    EXPECT_DOUBLE_EQ(table.evaluate(dx * 3).value, std::sin(dx * 3));
    double error = 0.0;
    for (int i = 0; i + 1 < nodes; ++i) {
      const double midpoint = dx * (i + 0.5);
      error = std::max(error, std::abs(table.evaluate(midpoint).value - f(midpoint)));
    }
    if (previous_error > 0) {
      EXPECT_NEAR(previous_error / error, 16.0, 1.0);
    }
    previous_error = error;
  }
}

TEST(UniformHermiteTable, SlopeIsTheDerivativeOfTheInterpolant) {
  // Compare with central differences of the interpolant itself (not of sin): the slope
  // must be exact for the piecewise cubic. Step 1e-6 inside an interval on O(1) values:
  // truncation ~1e-12 * |p'''|, roundoff ~1e-10: bound 1e-8.
  const auto table = tabulate([](double x) { return std::sin(3 * x); },
                              [](double x) { return 3 * std::cos(3 * x); }, 0.0, 0.25, 9);
  for (double x = 0.01; x < 1.99; x += 0.0731) {
    const double step = 1e-6;
    const double fd = (table.evaluate(x + step).value - table.evaluate(x - step).value) / (2 * step);
    EXPECT_NEAR(table.evaluate(x).slope, fd, 1e-8) << x;
  }
  // C1 at a node: the slope there is the nodal slope from both sides.
  EXPECT_NEAR(table.evaluate(0.5 - 1e-12).slope, 3 * std::cos(1.5), 1e-9);
  EXPECT_NEAR(table.evaluate(0.5 + 1e-12).slope, 3 * std::cos(1.5), 1e-9);
}

TEST(UniformHermiteTable, RejectsBadInput) {
  EXPECT_THROW(twb::UniformHermiteTable(0.0, 1.0, {1.0}, {0.0}), twb::InternalError);
  EXPECT_THROW(twb::UniformHermiteTable(0.0, 0.0, {1.0, 2.0}, {0.0, 0.0}), twb::InternalError);
  EXPECT_THROW(twb::UniformHermiteTable(0.0, 1.0, {1.0, 2.0}, {0.0}), twb::InternalError);
}

}  // namespace
