#include "solver/sparse_matrix_fill.h"

#include <algorithm>
#include <cmath>

#include <sunmatrix/sunmatrix_sparse.h>

namespace twb {

bool fill_sparse_matrix(SUNMatrix J, const SparsePattern& pattern, std::span<const double> values) {
  std::copy(pattern.row_start.begin(), pattern.row_start.end(), SUNSparseMatrix_IndexPointers(J));
  std::copy(pattern.column.begin(), pattern.column.end(), SUNSparseMatrix_IndexValues(J));
  std::copy(values.begin(), values.end(), SUNSparseMatrix_Data(J));
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace twb
