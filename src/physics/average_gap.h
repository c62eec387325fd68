// Average gap h_T of Patir & Cheng for Gaussian combined roughness, docs/physics.md section 3,
// paper eq [6]:  h_T = integral over delta > -h of (h + delta) G(delta) d delta,
// G = N(0, sigma^2), in closed form
//   h_T = (h/2) [1 + erf(h/(sigma sqrt2))] + sigma/sqrt(2 pi) exp(-h^2/(2 sigma^2)).
#pragma once

#include <span>

#include "physics/value_slope.h"

namespace twb {

// Value (m) and d h_T / dh = [1 + erf(h/(sigma sqrt2))]/2 (dimensionless).
// Always positive for any h (including h <= 0), equal to h within 1.3e-4 for h >= 3 sigma.
ValueSlope average_gap(double h, double sigma);
// d²h_T/dh² = G(h) = exp(−h²/(2σ²))/(σ√(2π)) (1/m): how the content's slope changes with
// the gap (the film's squeeze, docs/physics.md section 19); 0 where average_gap returns
// {h, 1} (below 1e-16/σ there).
double average_gap_curvature(double h, double sigma);
// ∂h_T/∂σ = exp(−h²/(2σ²))/√(2π) (dimensionless): h_T = σ·A(h/σ), so its slope in σ is
// A(x) − x·A'(x) (a face's roughness that changes as it runs in, docs/physics.md section 20).
double average_gap_by_sigma(double h, double sigma);
// ∂²h_T/∂h∂σ = −(h/σ)·G(h) (1/m): the slope's own slope in σ (the squeeze's content where
// the faces run in).
double average_gap_slope_by_sigma(double h, double sigma);
// The same at every gap of a batch, into out (same size), with exp and erfc vectorized
// (physics/batch_math.h): equal to the scalar values to a few ulp.
void average_gap(std::span<const double> h, double sigma, std::span<ValueSlope> out);

// h/(σ√2) from which average_gap returns {h, 1} without evaluating the closed form,
// which rounds to exactly those there (average_gap.cpp).
inline constexpr double exact_open_threshold = 6.0;

}  // namespace twb
