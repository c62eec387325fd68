// The batched exp, log and erfc, and the kernels built on them, against the scalar libm.
#include "physics/batch_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "physics/average_gap.h"
#include "physics/roelands_viscosity.h"

namespace {

// |a − b| in units of b's ulp.
double ulps(double a, double b) { return std::abs(a - b) / (std::nextafter(std::abs(b), INFINITY) - std::abs(b)); }

std::vector<double> spread(double from, double to, int n) {
  std::vector<double> x;
  for (int k = 0; k < n; ++k) x.push_back(n == 1 ? from : from + (to - from) * k / (n - 1));
  return x;
}

TEST(BatchMath, EqualsScalarLibmToAFewUlpAtEverySizeAndInPlace) {
  // Sizes 1…9 cover a full vector, partial tails and none.
  for (int n = 1; n <= 9; ++n) {
    const std::vector<double> e = spread(-700.0, 700.0, n), l = spread(1e-300, 1e300, n), c = spread(-5.0, 26.0, n);
    std::vector<double> y(static_cast<std::size_t>(n));
    twb::batch::exp(e, y);
    for (int k = 0; k < n; ++k) EXPECT_LE(ulps(y[k], std::exp(e[k])), 4.0) << "exp " << e[k];
    twb::batch::log(l, y);
    for (int k = 0; k < n; ++k) EXPECT_LE(ulps(y[k], std::log(l[k])), 4.0) << "log " << l[k];
    std::vector<double> in_place = c;
    twb::batch::erfc(in_place, in_place);
    for (int k = 0; k < n; ++k) EXPECT_LE(ulps(in_place[k], std::erfc(c[k])), 4.0) << "erfc " << c[k];
  }
}

TEST(BatchMath, RoelandsBatchEqualsScalarAboveAndBelowTheContinuation) {
  // The paper's oil; −250 … 2800 °C spans the linear continuation below −100 °C.
  const twb::RoelandsViscosity oil{6.31e-5, 3.545, 1.053};
  const std::vector<double> t = spread(273.15 - 250.0, 273.15 + 2800.0, 301);
  std::vector<twb::ValueSlope> mu(t.size());
  oil(t, mu);
  for (std::size_t k = 0; k < t.size(); ++k) {
    const twb::ValueSlope one = oil(t[k]);
    EXPECT_NEAR(mu[k].value / one.value, 1.0, 1e-14) << "T = " << t[k];
    EXPECT_NEAR(mu[k].slope / one.slope, 1.0, 1e-14) << "T = " << t[k];
  }
}

TEST(BatchMath, AverageGapBatchEqualsScalarClosedOpenAndFarOpen) {
  const double sigma = 0.728e-6;
  std::vector<double> h = spread(-8.0 * sigma, 40.0 * sigma, 481);
  h.push_back(0.0);
  std::vector<twb::ValueSlope> gap(h.size());
  twb::average_gap(h, sigma, gap);
  for (std::size_t k = 0; k < h.size(); ++k) {
    const twb::ValueSlope one = twb::average_gap(h[k], sigma);
    // Where the gap is closed, h·(erfc/2) and the Gaussian term nearly cancel (h_T ~
    // σφ(H)/H²): a few ulp in either grow by about H².
    const double H = h[k] / sigma;
    EXPECT_NEAR(gap[k].value / one.value, 1.0, 1e-14 * std::max(1.0, H * H)) << "h/sigma = " << H;
    EXPECT_NEAR(gap[k].slope, one.slope, 1e-15) << "h/sigma = " << h[k] / sigma;
    // Beyond the open threshold both are {h, 1} exactly.
    if (h[k] >= twb::exact_open_threshold * std::numbers::sqrt2 * sigma) {
      EXPECT_EQ(gap[k].value, h[k]);
      EXPECT_EQ(gap[k].slope, 1.0);
    }
  }
}

}  // namespace
