#include "physics/roelands_viscosity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "physics/batch_math.h"

namespace twb {

namespace {
constexpr double kelvin_at_zero_celsius = 273.15;
constexpr double roelands_temperature_scale = 135.0;  // C, eq [17]

// exponent(T) = G0 (1 + T_C/135)^(-S0) and d exponent/dT = -S0/(135 + T_C) * exponent,
// from base^(−S0) = exp(−S0 log base), at a temperature above the continuation.
ValueSlope exponent_from_power(double g0, double s0, double t_c, double power) {
  const double exponent = g0 * power;
  return ValueSlope{exponent, -s0 * exponent / (roelands_temperature_scale + t_c)};
}

double base(double t_c) { return 1.0 + t_c / roelands_temperature_scale; }

}  // namespace

ValueSlope RoelandsViscosity::exponent(double celsius) const {
  // base^(−S0) and 10^exponent through exp and log: the same values to rounding, at
  // about half the cost of two pow calls (this kernel runs at every Gauss point).
  const auto at = [this](double t_c) {
    return exponent_from_power(g0, s0, t_c, std::exp(-s0 * std::log(base(t_c))));
  };
  if (celsius >= continuation_celsius) return at(celsius);
  // Linear continuation of log10(mu) below the fit's useful range (see header).
  const ValueSlope at_edge = at(continuation_celsius);
  return {at_edge.value + at_edge.slope * (celsius - continuation_celsius), at_edge.slope};
}

ValueSlope RoelandsViscosity::operator()(double temperature_K) const {
  const ValueSlope e = exponent(temperature_K - kelvin_at_zero_celsius);
  const double mu = mu_infinity * std::exp(std::numbers::ln10 * e.value);
  return {mu, mu * std::numbers::ln10 * e.slope};
}

void RoelandsViscosity::operator()(std::span<const double> temperature_K, std::span<ValueSlope> out) const {
  // The scalar operator's arithmetic, with its exp and log taken over the batch.
  constexpr std::size_t chunk = 64;
  std::array<double, chunk> celsius, work, power;
  const ValueSlope at_edge = exponent(continuation_celsius);
  for (std::size_t start = 0; start < temperature_K.size(); start += chunk) {
    const std::size_t n = std::min(chunk, temperature_K.size() - start);
    const std::span<double> w(work.data(), n), p(power.data(), n);
    for (std::size_t k = 0; k < n; ++k) {
      celsius[k] = temperature_K[start + k] - kelvin_at_zero_celsius;
      work[k] = base(std::max(celsius[k], continuation_celsius));
    }
    batch::log(w, w);
    for (std::size_t k = 0; k < n; ++k) work[k] *= -s0;
    batch::exp(w, p);
    for (std::size_t k = 0; k < n; ++k) {
      const ValueSlope e = celsius[k] >= continuation_celsius
                               ? exponent_from_power(g0, s0, celsius[k], power[k])
                               : ValueSlope{at_edge.value + at_edge.slope * (celsius[k] - continuation_celsius),
                                            at_edge.slope};
      work[k] = std::numbers::ln10 * e.value;
      power[k] = e.slope;  // d exponent/dT, kept until the viscosity is known
    }
    std::array<double, chunk> mu;
    batch::exp(w, std::span<double>(mu.data(), n));
    for (std::size_t k = 0; k < n; ++k) {
      const double m = mu_infinity * mu[k];
      out[start + k] = {m, m * std::numbers::ln10 * power[k]};
    }
  }
}

}  // namespace twb
