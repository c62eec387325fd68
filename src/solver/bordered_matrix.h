// The sparse matrix of a square system with one more unknown and one more equation:
//
//     [ A   c ]        A: n×n in a fixed sparse pattern,
//     [ rᵀ  d ]        c, r: dense columns of length n, d: a number.
//
// Pseudo-arclength continuation (a parameter column, a normalization row) and the
// minimally augmented fold system (a border column, the test function's gradient)
// both have this shape. The pattern is built once, so KLU's symbolic analysis holds for
// the whole continuation.
#pragma once

#include <span>

#include "system/sparse_pattern.h"

namespace twb {

class BorderedMatrix {
 public:
  explicit BorderedMatrix(const SparsePattern& base);

  const SparsePattern& pattern() const { return pattern_; }
  Index base_size() const { return n_; }

  // Writes the values of [A c; rᵀ d] in pattern() order; a_values in the base pattern's.
  void assemble(std::span<const double> a_values, std::span<const double> column, std::span<const double> row,
                double corner, std::span<double> values) const;

 private:
  Index n_;
  SparsePattern pattern_;
};

}  // namespace twb
