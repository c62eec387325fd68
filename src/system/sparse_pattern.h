// The sparsity pattern of a system's Jacobian: what the model assembles into and the
// solvers factor. Below both, so that neither depends on the other.
#pragma once

#include <cstdint>
#include <vector>

namespace twb {

using Index = std::int64_t;  // sunindextype on Debian 12's SUNDIALS

// Row-compressed (CSR) matrix with sorted columns in every row.
struct SparsePattern {
  Index rows = 0, cols = 0;
  std::vector<Index> row_start;  // rows + 1
  std::vector<Index> column;     // nnz
  Index nnz() const { return Index(column.size()); }
  // Position of (r, c) in column/value arrays, or -1.
  Index find(Index r, Index c) const;
};

}  // namespace twb
