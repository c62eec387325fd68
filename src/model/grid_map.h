// Bilinear interpolation between two Nr × Nθ index grids spread uniformly over the same
// annulus (docs/physics.md section 10): a node of the target lies at the same fractions
// of radius span and turn on the source grid, so interpolation there is second-order
// accurate. θ is periodic.
#pragma once

#include <algorithm>
#include <cmath>

namespace twb {

struct GridMap {
  int src_nr, src_nt, dst_nr, dst_nt;

  // The source field value(i, j) at the point that is node (i, j) of the target grid.
  template <class Value>
  double at(int i, int j, const Value& value) const {
    const double s = dst_nr > 1 ? double(i) * (src_nr - 1) / (dst_nr - 1) : 0.0;
    const int i0 = std::min(int(std::floor(s)), std::max(src_nr - 2, 0));
    const double ti = src_nr > 1 ? s - i0 : 0.0;
    const int i1 = std::min(i0 + 1, src_nr - 1);
    const double a = double(j) * src_nt / dst_nt;
    const int j0 = int(std::floor(a)) % src_nt;
    const double tj = a - std::floor(a);
    const int j1 = (j0 + 1) % src_nt;
    return (1 - ti) * ((1 - tj) * value(i0, j0) + tj * value(i0, j1)) +
           ti * ((1 - tj) * value(i1, j0) + tj * value(i1, j1));
  }
};

}  // namespace twb
