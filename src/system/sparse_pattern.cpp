#include "system/sparse_pattern.h"

#include <algorithm>

namespace twb {

Index SparsePattern::find(Index r, Index c) const {
  const auto first = column.begin() + row_start[r];
  const auto last = column.begin() + row_start[r + 1];
  const auto it = std::lower_bound(first, last, c);
  return (it != last && *it == c) ? Index(it - column.begin()) : -1;
}

}  // namespace twb
