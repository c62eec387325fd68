// Piecewise cubic Hermite interpolant on a uniform grid from nodal values and slopes.
// C1 across nodes; evaluate() returns the interpolant and its exact derivative, which
// is what a Newton Jacobian needs (not a finite-difference or a separately fitted slope).
#pragma once

#include <cstddef>
#include <vector>

#include "twb/physics/value_slope.h"

namespace twb {

class UniformHermiteTable {
 public:
  UniformHermiteTable() = default;
  // Node i at x = x_first + i*spacing, i = 0..values.size()-1 (at least 2 nodes).
  UniformHermiteTable(double x_first, double spacing, std::vector<double> values,
                      std::vector<double> slopes);

  // Only for x_first() <= x <= x_last(); callers handle extrapolation.
  ValueSlope evaluate(double x) const;

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
