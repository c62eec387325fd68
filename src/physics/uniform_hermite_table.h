// Piecewise cubic Hermite interpolant on a uniform grid from nodal values and slopes.
// C1 across nodes; evaluate() returns the interpolant and its exact derivative, which
// is what a Newton Jacobian needs (not a finite-difference or a separately fitted slope).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "physics/value_slope.h"

namespace twb {

class UniformHermiteTable {
 public:
  UniformHermiteTable() = default;
  // Node i at x = x_first + i*spacing, i = 0..values.size()-1 (at least 2 nodes).
  UniformHermiteTable(double x_first, double spacing, std::vector<double> values,
                      std::vector<double> slopes);

  // Only for x_first() <= x <= x_last(); callers handle extrapolation. Inline: contact
  // evaluates it at every Gauss point of every near-contact cell.
  ValueSlope evaluate(double x) const {
    const double position = (x - x_first_) / spacing_;
    const auto last_interval = static_cast<std::ptrdiff_t>(values_.size()) - 2;
    const auto i = std::clamp(static_cast<std::ptrdiff_t>(std::floor(position)),
                              std::ptrdiff_t{0}, last_interval);
    const double t = position - static_cast<double>(i);
    const double y0 = values_[i], y1 = values_[i + 1];
    const double m0 = slopes_[i] * spacing_, m1 = slopes_[i + 1] * spacing_;
    // Cubic Hermite basis in t in [0,1]: h00 = 2t^3-3t^2+1, h10 = t^3-2t^2+t,
    // h01 = -2t^3+3t^2, h11 = t^3-t^2; y = h00 y0 + h10 m0 + h01 y1 + h11 m1.
    const double t2 = t * t, t3 = t2 * t;
    const double value = (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * m0 +
                         (3 * t2 - 2 * t3) * y1 + (t3 - t2) * m1;
    const double d_dt = (6 * t2 - 6 * t) * (y0 - y1) + (3 * t2 - 4 * t + 1) * m0 +
                        (3 * t2 - 2 * t) * m1;
    return {value, d_dt / spacing_};
  }

  double x_first() const { return x_first_; }
  double x_last() const { return x_first_ + spacing_ * static_cast<double>(size() - 1); }
  double spacing() const { return spacing_; }
  std::size_t size() const { return values_.size(); }
  double node_value(std::size_t i) const { return values_[i]; }
  double node_slope(std::size_t i) const { return slopes_[i]; }

 private:
  double x_first_ = 0.0;
  double spacing_ = 1.0;
  std::vector<double> values_;
  std::vector<double> slopes_;
};

}  // namespace twb
