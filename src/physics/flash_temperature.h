// Blok's flash temperature of a sliding asperity contact (docs/physics.md section 8,
// scuffing): the temperature rise of a circular contact of radius a through which a
// uniform heat flux q enters a half-space, as Tian and Kennedy (1994) fitted the exact
// solutions (Jaeger 1942) across every Péclet number Pe = V·a/(2κ) of the source's speed V
// over the body:
//
//   maximum rise  θ_max = (q·a/k) · 2/sqrt(π·(1.273 + Pe))
//   mean rise     θ_avg = (q·a/k) · 1.22/sqrt(π·(0.6575 + Pe))
//
// Both meet the stationary source's closed forms as Pe → 0 (θ_max = q·a/k at the centre,
// θ_avg = 8/(3π)·q·a/k over the circle) and Jaeger's fast source as Pe → ∞ (the heat
// entering each strip along the motion as into a semi-infinite solid for the strip's
// transit time: θ_max = (2/sqrt(π))·(q·a/k)/sqrt(Pe) at the trailing edge).
//
// Two bodies share the contact's heat as Blok postulated: each takes the part that brings
// its surface to the same rise, so the rise is q·a / (k1/F1 + k2/F2), F the
// dimensionless factors above for each body's own Péclet number.
#pragma once

namespace twb {

// The dimensionless rises θ·k/(q·a) of one body at Péclet number Pe >= 0.
double flash_maximum_factor(double peclet);
double flash_mean_factor(double peclet);

struct FlashBody {
  double conductivity = 0.0;  // k, W/(m K)
  double diffusivity = 0.0;   // κ = k/(ρ c), m²/s
  double speed = 0.0;         // the contact's speed over this body's surface, m/s
};

// The maximum flash temperature rise (K) of a contact of radius a (m) with heat flux q
// (W/m²) shared by two bodies.
double flash_temperature_rise(double heat_flux, double contact_radius, const FlashBody& first, const FlashBody& second);

}  // namespace twb
