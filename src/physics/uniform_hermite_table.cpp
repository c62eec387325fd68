#include "twb/physics/uniform_hermite_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace twb {

UniformHermiteTable::UniformHermiteTable(double x_first, double spacing,
                                         std::vector<double> values,
                                         std::vector<double> slopes)
    : x_first_(x_first), spacing_(spacing), values_(std::move(values)),
      slopes_(std::move(slopes)) {
  if (values_.size() < 2 || values_.size() != slopes_.size() || !(spacing_ > 0.0))
    throw std::invalid_argument("UniformHermiteTable: need >= 2 nodes, equal sizes, spacing > 0");
}

ValueSlope UniformHermiteTable::evaluate(double x) const {
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

}  // namespace twb
