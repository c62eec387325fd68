#include "twb/physics/roelands_viscosity.h"

#include <cmath>
#include <numbers>

namespace twb {

namespace {
constexpr double kelvin_at_zero_celsius = 273.15;
constexpr double roelands_temperature_scale = 135.0;  // C, eq [17]
}  // namespace

ValueSlope RoelandsViscosity::operator()(double temperature_K) const {
  const double celsius = temperature_K - kelvin_at_zero_celsius;
  // exponent(T) = G0 (1 + T_C/135)^(-S0); d exponent/dT = -S0/(135 + T_C) * exponent.
  const auto exponent_and_slope = [this](double t_c) {
    const double base = 1.0 + t_c / roelands_temperature_scale;
    // base^(−S0) and 10^exponent through exp and log: the same values to rounding, at
    // about half the cost of two pow calls (this kernel runs at every Gauss point).
    const double exponent = g0 * std::exp(-s0 * std::log(base));
    return ValueSlope{exponent, -s0 * exponent / (roelands_temperature_scale + t_c)};
  };
  ValueSlope exponent;
  if (celsius >= continuation_celsius) {
    exponent = exponent_and_slope(celsius);
  } else {
    // Linear continuation of log10(mu) below the fit's useful range (see header).
    const ValueSlope at_edge = exponent_and_slope(continuation_celsius);
    exponent = {at_edge.value + at_edge.slope * (celsius - continuation_celsius),
                at_edge.slope};
  }
  const double mu = mu_infinity * std::exp(std::numbers::ln10 * exponent.value);
  return {mu, mu * std::numbers::ln10 * exponent.slope};
}

}  // namespace twb
