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
  // Its grid couples so many fields per node that nested dissection orders it better than
  // minimum degree at any size (sparse_lu.h): the elastic washer's plate, whose two
  // unknowns per node join the films' (on the paper's 9 x 66 mesh, 3458 unknowns: 624k
  // entries in the factors and 26 ms a refactorization against AMD's 1274k and 136 ms).
  // Patterns built on it (bordered, with a capacity's diagonal) keep it.
  bool prefers_nested_dissection = false;
  Index nnz() const { return Index(column.size()); }
  // Position of (r, c) in column/value arrays, or -1.
  Index find(Index r, Index c) const;
};

}  // namespace twb
