#include "physics/modulus_curve.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace twb {
namespace {

// The PCHIP slopes (Fritsch and Butland's, as Boost's pchip takes them: the secants at
// the ends, the weighted harmonic mean of the neighbouring secants inside, zero at an
// extremum), which keep each piece monotone. Boost's pchip itself wants four points and,
// in Debian 12's Boost, does not compile for double (an unqualified isnan): its
// cubic_hermite evaluates. Two points give the straight line between them.
std::vector<double> monotone_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> s(n);
  const auto secant = [&](std::size_t k) { return (y[k + 1] - y[k]) / (x[k + 1] - x[k]); };
  s[0] = secant(0);
  s[n - 1] = secant(n - 2);
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double before = secant(k - 1), after = secant(k);
    const double h_before = x[k] - x[k - 1], h_after = x[k + 1] - x[k];
    const double w1 = 2 * h_after + h_before, w2 = h_after + 2 * h_before;
    s[k] = before * after <= 0.0 ? 0.0 : (w1 + w2) / (w1 / before + w2 / after);
  }
  return s;
}

}  // namespace

ModulusCurve::ModulusCurve(std::span<const double> temperatures, std::span<const double> moduli) {
  if (temperatures.empty() || temperatures.size() != moduli.size())
    throw std::invalid_argument(fmt::format("a modulus curve needs as many moduli as temperatures, at least one "
                                            "(got {} and {})",
                                            temperatures.size(), moduli.size()));
  std::vector<double> t(temperatures.begin(), temperatures.end()), ln_e;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!(moduli[k] > 0.0) || !std::isfinite(moduli[k]) || !std::isfinite(t[k]))
      throw std::invalid_argument(fmt::format("a modulus curve's point {} is not a finite temperature with a positive "
                                              "modulus",
                                              k + 1));
    if (k > 0 && !(t[k] > t[k - 1]))
      throw std::invalid_argument(fmt::format("a modulus curve's temperatures must rise: point {} is not above "
                                              "point {}",
                                              k + 1, k));
    ln_e.push_back(std::log(moduli[k]));
  }
  lowest_ = t.front();
  highest_ = t.back();
  lowest_modulus_ = moduli.front();
  highest_modulus_ = moduli.back();
  if (t.size() > 1) {
    std::vector<double> slopes = monotone_slopes(t, ln_e);
    curve_.emplace_back(std::move(t), std::move(ln_e), std::move(slopes));
  }
}

ModulusCurve::Value ModulusCurve::at(double temperature) const {
  // A NaN would pass both range checks and index past the interpolant's data.
  if (std::isnan(temperature)) throw std::invalid_argument("a modulus curve at a temperature that is not a number");
  // A single point is a constant modulus: no data to leave.
  if (curve_.empty()) return {lowest_modulus_, 0.0, Value::Range::inside};
  // Held at the data's ends, exactly their values.
  if (temperature < lowest_) return {lowest_modulus_, 0.0, Value::Range::below};
  if (temperature > highest_) return {highest_modulus_, 0.0, Value::Range::above};
  const auto& curve = curve_.front();
  const double modulus = std::exp(curve(temperature));
  return {modulus, modulus * curve.prime(temperature), Value::Range::inside};
}

}  // namespace twb
