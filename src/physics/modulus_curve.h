// A material's Young's modulus against temperature from its data sheet's points
// (docs/physics.md section 23, [M1]): ln E by the monotone piecewise-cubic Hermite
// interpolant of (T_k, ln E_k), held at the nearer end outside the data.
#pragma once

#include <span>
#include <vector>

#include <boost/math/interpolators/cubic_hermite.hpp>

namespace twb {

class ModulusCurve {
 public:
  // temperatures (K) strictly ascending, moduli (Pa) positive, the same count ≥ 1 (one
  // point: a constant modulus, inside its data at every temperature).
  // std::invalid_argument otherwise.
  ModulusCurve(std::span<const double> temperatures, std::span<const double> moduli);

  struct Value {
    double modulus = 0.0;  // Pa
    double slope = 0.0;    // dE/dT, Pa/K; 0 outside the data (held)
    // Where the temperature lies against the data: inside, or held at an end.
    enum class Range { inside, below, above } range = Range::inside;
  };
  // std::invalid_argument for a NaN temperature.
  Value at(double temperature) const;

  double lowest_temperature() const { return lowest_; }
  double highest_temperature() const { return highest_; }

 private:
  double lowest_, highest_;
  double lowest_modulus_, highest_modulus_;
  std::vector<boost::math::interpolators::cubic_hermite<std::vector<double>>> curve_;  // none (one point) or one
};

}  // namespace twb
