#include "physics/summit_statistics.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace twb {

SpectralMoments spectral_moments(std::span<const double> heights, double spacing) {
  const std::size_t n = heights.size();
  if (n < 3) throw std::invalid_argument("a profile needs at least three heights for its curvature");
  if (!(spacing > 0)) throw std::invalid_argument("the sampling interval must be positive");
  // Kahan-free sums are enough: n·ε relative for n up to millions of samples.
  double mean = 0;
  for (double z : heights) mean += z;
  mean /= static_cast<double>(n);
  double m0 = 0;
  for (double z : heights) m0 += (z - mean) * (z - mean);
  m0 /= static_cast<double>(n);
  // The mean drops out of the differences.
  double m2 = 0, m4 = 0;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double slope = (heights[k + 1] - heights[k - 1]) / (2 * spacing);
    const double curvature = (heights[k + 1] - 2 * heights[k] + heights[k - 1]) / (spacing * spacing);
    m2 += slope * slope;
    m4 += curvature * curvature;
  }
  m2 /= static_cast<double>(n - 2);
  m4 /= static_cast<double>(n - 2);
  if (!(m0 > 0 && m2 > 0 && m4 > 0))
    throw std::invalid_argument("the profile is flat (or a straight line): it has no summits");
  return {m0, m2, m4};
}

SpectralMoments combined(const SpectralMoments& a, const SpectralMoments& b) {
  return {a.m0 + b.m0, a.m2 + b.m2, a.m4 + b.m4};
}

SummitStatistics mccool_summits(const SpectralMoments& m) {
  const double alpha = m.bandwidth();
  constexpr double kSummitVarianceShare = 0.8968;
  if (!(alpha > kSummitVarianceShare))
    throw std::invalid_argument("bandwidth parameter at or below 0.8968: no summit-height variance");
  const double pi = std::numbers::pi;
  return {.density = m.m4 / (6 * pi * std::sqrt(3.0) * m.m2),
          .radius = 0.375 * std::sqrt(pi / m.m4),
          .sigma = std::sqrt(1 - kSummitVarianceShare / alpha) * std::sqrt(m.m0)};
}

}  // namespace twb
