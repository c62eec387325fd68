// McCool's summit statistics from a profile (docs/physics.md section 13), on synthetic
// Gaussian profiles whose discrete spectral moments are known in closed form.
#include "physics/summit_statistics.h"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace twb {
namespace {

constexpr double kPi = std::numbers::pi;

// A sum of many sinusoids of random phase (Gaussian by the central limit theorem), each
// with a whole number of periods over the N samples, so that over the whole profile the
// squares average to a²/2 and the cross terms to zero exactly.
struct SyntheticProfile {
  std::vector<double> heights;
  double spacing = 0;
  SpectralMoments expected;  // of the centred differences, exact for whole periods
  double slope_bound = 0, curvature_bound = 0;  // max |dz/dx|, |d²z/dx²| of the differences
};

SyntheticProfile synthetic(int n, double spacing, int lowest_mode, int highest_mode, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> phase(0, 2 * kPi);
  SyntheticProfile p;
  p.spacing = spacing;
  p.heights.assign(n, 0.0);
  for (int mode = lowest_mode; mode <= highest_mode; ++mode) {
    const double k = 2 * kPi * mode / (n * spacing);
    const double a = 1e-6 * std::pow(static_cast<double>(mode) / lowest_mode, -1.5);  // a falling spectrum
    const double phi = phase(random);
    for (int j = 0; j < n; ++j) p.heights[j] += a * std::cos(k * j * spacing + phi);
    // Transfer functions of the centred differences: sin(kΔ)/Δ and 2(1 − cos kΔ)/Δ².
    const double slope_gain = std::sin(k * spacing) / spacing;
    const double curvature_gain = 2 * (1 - std::cos(k * spacing)) / (spacing * spacing);
    p.expected.m0 += a * a / 2;
    p.expected.m2 += a * a / 2 * slope_gain * slope_gain;
    p.expected.m4 += a * a / 2 * curvature_gain * curvature_gain;
    p.slope_bound += a * std::abs(slope_gain);
    p.curvature_bound += a * curvature_gain;
  }
  return p;
}

TEST(SpectralMoments, SyntheticGaussianProfileHasItsKnownMoments) {
  const int n = 1 << 16;
  const SyntheticProfile p = synthetic(n, 0.5e-6, 8, 400, 13);
  const SpectralMoments m = spectral_moments(p.heights, p.spacing);
  // m0 averages whole periods: exact but for rounding in the n-term sums (n ε ≈ 7e-12).
  EXPECT_NEAR(m.m0, p.expected.m0, 1e-10 * p.expected.m0);
  // The differences exist at n − 2 samples: the two left out change a whole-period mean
  // of g² by at most 2·max g²/(n − 2), with max |g| at most the sum of the amplitudes.
  const double window = 2.0 / (n - 2);
  EXPECT_NEAR(m.m2, p.expected.m2, window * p.slope_bound * p.slope_bound + 1e-10 * p.expected.m2);
  EXPECT_NEAR(m.m4, p.expected.m4, window * p.curvature_bound * p.curvature_bound + 1e-10 * p.expected.m4);
  // The bound is tight enough to mean something: well below the moments themselves.
  EXPECT_LT(window * p.curvature_bound * p.curvature_bound, 0.05 * p.expected.m4);
}

TEST(SpectralMoments, MeanAndSpacingEnterAsTheyShould) {
  const SyntheticProfile p = synthetic(4096, 1e-6, 4, 200, 7);
  std::vector<double> raised = p.heights;
  for (double& z : raised) z += 3e-3;  // a datum far from the mean line
  const SpectralMoments a = spectral_moments(p.heights, p.spacing);
  const SpectralMoments b = spectral_moments(raised, p.spacing);
  EXPECT_NEAR(b.m0, a.m0, 1e-9 * a.m0);  // rounding of 3e-3 against 1e-6 heights
  EXPECT_NEAR(b.m2, a.m2, 1e-6 * a.m2);
  // The same heights read at twice the spacing: slopes halve, curvatures quarter.
  const SpectralMoments c = spectral_moments(p.heights, 2 * p.spacing);
  EXPECT_DOUBLE_EQ(c.m0, a.m0);
  EXPECT_NEAR(c.m2, a.m2 / 4, 1e-14 * a.m2);
  EXPECT_NEAR(c.m4, a.m4 / 16, 1e-14 * a.m4);
}

TEST(SpectralMoments, FlatOrShortProfilesAreRefused) {
  EXPECT_THROW(spectral_moments(std::vector<double>{1.0, 2.0}, 1e-6), std::invalid_argument);
  EXPECT_THROW(spectral_moments(std::vector<double>(100, 4e-7), 1e-6), std::invalid_argument);
  std::vector<double> ramp(100);
  for (std::size_t k = 0; k < ramp.size(); ++k) ramp[k] = 0.25 * static_cast<double>(k);  // exact differences
  EXPECT_THROW(spectral_moments(ramp, 1e-6), std::invalid_argument);  // no curvature: no summits
  EXPECT_THROW(spectral_moments(std::vector<double>{1.0, 2.0, 0.0}, 0.0), std::invalid_argument);
}

TEST(McCoolSummits, RelationsOfMcCool1986) {
  const SpectralMoments m{.m0 = 0.5e-12, .m2 = 9e-3, .m4 = 1.1e9};
  const SummitStatistics s = mccool_summits(m);
  const double alpha = 0.5e-12 * 1.1e9 / (9e-3 * 9e-3);
  EXPECT_DOUBLE_EQ(m.bandwidth(), alpha);
  EXPECT_DOUBLE_EQ(s.density, 1.1e9 / (6 * kPi * std::sqrt(3.0) * 9e-3));
  EXPECT_DOUBLE_EQ(s.radius, 0.375 * std::sqrt(kPi / 1.1e9));
  EXPECT_DOUBLE_EQ(s.sigma, std::sqrt(1 - 0.8968 / alpha) * std::sqrt(0.5e-12));
  // ηRσs depends on the bandwidth alone: (0.375√π/(6π√3))·√α·√(1 − 0.8968/α).
  EXPECT_NEAR(s.density * s.radius * s.sigma,
              0.375 * std::sqrt(kPi) / (6 * kPi * std::sqrt(3.0)) * std::sqrt(alpha) * std::sqrt(1 - 0.8968 / alpha),
              1e-14);
}

TEST(McCoolSummits, NarrowBandHasNoSummitVariance) {
  EXPECT_THROW(mccool_summits({.m0 = 1e-12, .m2 = 1e-2, .m4 = 0.8e8}), std::invalid_argument);
}

TEST(McCoolSummits, TwoFacesAddTheirMoments) {
  // Two faces with disjoint bands of whole-period modes: the sum surface's cross terms
  // vanish over the profile, so its moments are the faces' sums up to the two samples
  // the differences leave out (as in the first test).
  const int n = 1 << 14;
  const SyntheticProfile a = synthetic(n, 1e-6, 4, 100, 1), b = synthetic(n, 1e-6, 101, 300, 2);
  std::vector<double> sum(n);
  for (int k = 0; k < n; ++k) sum[k] = a.heights[k] + b.heights[k];
  const SpectralMoments both = combined(spectral_moments(a.heights, 1e-6), spectral_moments(b.heights, 1e-6));
  const SpectralMoments direct = spectral_moments(sum, 1e-6);
  const double window = 2.0 / (n - 2);
  const double slope = a.slope_bound + b.slope_bound, curvature = a.curvature_bound + b.curvature_bound;
  EXPECT_NEAR(direct.m0, both.m0, 1e-10 * both.m0);
  EXPECT_NEAR(direct.m2, both.m2, 2 * window * slope * slope);
  EXPECT_NEAR(direct.m4, both.m4, 2 * window * curvature * curvature);
}

}  // namespace
}  // namespace twb
