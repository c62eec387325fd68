#include "physics/flash_temperature.h"

#include <cmath>
#include <numbers>

namespace twb {

double flash_maximum_factor(double peclet) { return 2.0 / std::sqrt(std::numbers::pi * (1.273 + peclet)); }

double flash_mean_factor(double peclet) { return 1.22 / std::sqrt(std::numbers::pi * (0.6575 + peclet)); }

double flash_temperature_rise(double heat_flux, double contact_radius, const FlashBody& first,
                              const FlashBody& second) {
  if (!(heat_flux > 0.0) || !(contact_radius > 0.0)) return 0.0;
  // Each body's surface rises by q_k·a/k_k·F_k; equal rises with q_1 + q_2 = q.
  const auto per_flux = [&](const FlashBody& b) {
    const double peclet = b.speed * contact_radius / (2.0 * b.diffusivity);
    return b.conductivity / flash_maximum_factor(peclet);
  };
  return heat_flux * contact_radius / (per_flux(first) + per_flux(second));
}

}  // namespace twb
