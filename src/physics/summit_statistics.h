// Summit statistics of a rough surface from a measured profile (docs/physics.md section 13,
// McCool 1986): the spectral moments of the heights, and from them the summit density,
// the summit radius and the summit-height standard deviation of an isotropic Gaussian
// surface, the three inputs of the statistical contact model (section 4).
#pragma once

#include <span>

namespace twb {

// Spectral moments of a profile: m0 = <z²>, m2 = <(dz/dx)²>, m4 = <(d²z/dx²)²>, the
// mean removed, the slopes and curvatures by centred differences (so over the samples
// that have both neighbours).
struct SpectralMoments {
  double m0 = 0;  // m²
  double m2 = 0;  // 1 (slope²)
  double m4 = 0;  // 1/m² (curvature²)
  // The bandwidth parameter α_b = m0·m4/m2² (at least about 1 for any profile; McCool's relations
  // need a broad band, α_b ≳ 5).
  double bandwidth() const { return m0 * m4 / (m2 * m2); }
};

// The moments of heights z sampled at uniform spacing (m). Needs at least three samples
// and a profile that is not flat (std::invalid_argument otherwise).
SpectralMoments spectral_moments(std::span<const double> heights, double spacing);

// The moments of the sum of two independent surfaces (e.g. the two faces of a film):
// the spectra, hence every moment, add.
SpectralMoments combined(const SpectralMoments& a, const SpectralMoments& b);

struct SummitStatistics {
  double density = 0;  // η, summits per m²
  double radius = 0;   // R, m
  double sigma = 0;    // σs, m
};

// McCool's relations for an isotropic Gaussian surface:
//   η = m4/(6π√3·m2),  R = 0.375·√(π/m4),  σs = √(1 − 0.8968/α_b)·√m0.
// std::invalid_argument when α_b ≤ 0.8968 (no real σs: not a random surface).
SummitStatistics mccool_summits(const SpectralMoments& moments);

// Below this bandwidth McCool's relations are outside the range he validated them on;
// the estimate is still given, with a warning.
inline constexpr double mccool_min_bandwidth = 5.0;

}  // namespace twb
