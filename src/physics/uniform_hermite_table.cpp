#include "physics/uniform_hermite_table.h"
#include "twb/error_family.h"

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
    throw InternalError("UniformHermiteTable: need >= 2 nodes, equal sizes, spacing > 0");
}

}  // namespace twb
