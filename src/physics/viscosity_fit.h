// The oil as users have it (docs/physics.md section 5, "The oil from its data sheet"):
// kinematic viscosities at 40 and 100 degC and a density, or a table of viscosities at
// temperatures, turned once into the Roelands law the model evaluates.
//  - Two points (a data sheet): ASTM D341's Walther relation through them,
//    log10 log10(ν + 0.7) = A − B·log10 T (ν in mm²/s, T in K), gives ν between and
//    beyond them; μ = ρ(T)·ν with ρ(T) = ρ_ref·(1 − α·(T − T_ref)). Roelands is fitted to
//    that μ(T) at 29 temperatures from 20 K below the lower point to 60 K above the upper.
//  - A table: Roelands fitted to its points; two points fix G0 and S0 with Roelands' own
//    μ∞ = 6.31e-5 Pa s.
// The fit is least squares in log10 μ. For a fixed μ∞ it is linear in (log10 G0, S0):
// log10(log10 μ − log10 μ∞) = log10 G0 − S0·log10(1 + T_C/135); μ∞ is the one nonlinear
// unknown, found by Brent's minimization of that linear fit's residual.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "physics/roelands_viscosity.h"

namespace twb {

struct ViscosityPoint {
  double temperature = 0.0;  // K
  double viscosity = 0.0;    // Pa s, dynamic
};

struct ViscosityFit {
  RoelandsViscosity law{};
  // The given points and the fitted law's relative error there, (μ_fit − μ)/μ.
  std::vector<ViscosityPoint> points;
  std::vector<double> relative_errors;
  double largest_error = 0.0;  // over every fitted temperature (Walther's samples included)
};

// Kinematic viscosity (m²/s) by the Walther relation through two points (K, m²/s).
double walther_viscosity(double t1, double nu1, double t2, double nu2, double temperature);

// Roelands through the points (dynamic viscosities, temperatures distinct, viscosities
// falling with temperature): μ∞ fitted too (at least three points), or given (two
// points are then met exactly).
ViscosityFit fit_roelands(const std::vector<ViscosityPoint>& points, std::optional<double> mu_infinity = {});

// A data sheet: kinematic viscosities nu40, nu100 (m²/s), the density at t_ref (kg/m³,
// K) and its volumetric expansion (1/K).
ViscosityFit fit_data_sheet(double nu40, double nu100, double density, double t_ref, double expansion);

}  // namespace twb
