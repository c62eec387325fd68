#include "physics/flow_factors.h"

#include <cmath>

namespace twb {

ValueSlope pressure_flow_factor(double H) {
  // Eq [2], isotropic roughness (gamma = 1).
  const double decay = 0.9 * std::exp(-0.56 * H);
  return {1.0 - decay, 0.56 * decay};
}

ValueSlope shear_flow_factor_Phi_s(double H) {
  if (H <= 0.0) return {0.0, 0.0};  // closed gap: no shear flow through it
  if (H <= 5.0) {
    // Eq [4] corrected (Patir & Cheng 1979): the exponent has +0.05 H^2.
    const double value = 1.899 * std::pow(H, 0.98) * std::exp(-0.92 * H + 0.05 * H * H);
    return {value, value * (0.98 / H - 0.92 + 0.1 * H)};
  }
  const double value = 1.126 * std::exp(-0.25 * H);  // eq [5]
  return {value, -0.25 * value};
}

double shear_flow_factor_weight(double sigma1, double sigma2) {
  const double variance = sigma1 * sigma1 + sigma2 * sigma2;
  if (variance <= 0.0) return 0.0;  // two smooth surfaces: no roughness-induced flow
  return (sigma1 * sigma1 - sigma2 * sigma2) / variance;
}

}  // namespace twb
