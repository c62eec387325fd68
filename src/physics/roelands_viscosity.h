// Pressure-independent Roelands viscosity, docs/physics.md section 5, paper eq [17]:
//   mu(T) = mu_inf * 10^( G0 * (1 + T_C/135)^(-S0) ),  T_C = T - 273.15.
#pragma once

#include <span>

#include "physics/value_slope.h"

namespace twb {

struct RoelandsViscosity {
  double mu_infinity;  // Pa s
  double g0;           // dimensionless
  double s0;           // dimensionless

  // Below this Celsius temperature the fit (regressed between ~24 and 100 C) is
  // meaningless and its exponent blows up at T_C = -135 (it already overflows a double
  // near -133 C). There log10(mu) is continued linearly with matching value and slope:
  // the result stays C1, monotone, positive and finite for every T_C > -770 C (any
  // non-negative kelvin, and Newton iterates down to about -500 K).
  static constexpr double continuation_celsius = -100.0;

  // Viscosity (Pa s) and d mu/dT (Pa s/K) at the temperature in kelvin.
  ValueSlope operator()(double temperature_K) const;
  // The same at every temperature of a batch, into out (same size), with exp and log
  // vectorized (physics/batch_math.h): equal to the scalar values to a few ulp.
  void operator()(std::span<const double> temperature_K, std::span<ValueSlope> out) const;

 private:
  // G0 (1 + T_C/135)^(-S0), continued below continuation_celsius, and its slope in T.
  ValueSlope exponent(double celsius) const;
};

}  // namespace twb
