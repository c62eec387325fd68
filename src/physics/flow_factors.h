// Patir & Cheng flow factors for isotropic Gaussian roughness, docs/physics.md section 3,
// paper eqs [2]-[5] (with the corrected exponent of [4]). Argument H = h/sigma with
// sigma the combined roughness sqrt(sigma1^2 + sigma2^2).
#pragma once

#include "physics/value_slope.h"

namespace twb {

// phi_x = phi_y = 1 - 0.9 exp(-0.56 H) (eq [2]). Used as is for H <= 0: the formula is
// smooth there, and the Poiseuille term is switched off separately by max(h,0)^3.
// Slope is d phi / dH.
ValueSlope pressure_flow_factor(double H);

// Phi_s(H) of eqs [4], [5] (Patir & Cheng 1979):
//   1.899 H^0.98 exp(-0.92 H + 0.05 H^2)  for 0 < H <= 5,
//   1.126 exp(-0.25 H)                     for H > 5.
// For H <= 0 the gap is closed and there is no shear flow through it: value 0, slope 0.
// The two branches meet at H = 5 to 9.5e-5 relative (not exactly: a small jump).
// Slope is d Phi_s / dH; it is unbounded as H -> 0+ (H^-0.02), finite for every H > 0.
ValueSlope shear_flow_factor_Phi_s(double H);

// Weight of Phi_s in phi_s = [(sigma1/sigma)^2 - (sigma2/sigma)^2] Phi_s (eq [3]),
// sigma = sqrt(sigma1^2 + sigma2^2). Zero for identical roughness, and 0 if both are 0.
double shear_flow_factor_weight(double sigma1, double sigma2);

}  // namespace twb
