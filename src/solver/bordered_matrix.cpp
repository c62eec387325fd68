#include "solver/bordered_matrix.h"
#include "twb/error_family.h"

#include <algorithm>
#include <stdexcept>

namespace twb {

// Row i < n keeps A's columns and gains column n at its end (columns stay sorted);
// row n holds every column. Base entry p of row i therefore moves to p + i.
BorderedMatrix::BorderedMatrix(const SparsePattern& base) : n_(base.rows) {
  if (base.rows != base.cols) throw InternalError("BorderedMatrix: the base matrix must be square");
  pattern_.rows = pattern_.cols = n_ + 1;
  pattern_.prefers_nested_dissection = base.prefers_nested_dissection;
  pattern_.row_start.reserve(std::size_t(n_ + 2));
  pattern_.column.reserve(std::size_t(base.nnz() + 2 * n_ + 1));
  pattern_.row_start.push_back(0);
  for (Index i = 0; i < n_; ++i) {
    for (Index p = base.row_start[std::size_t(i)]; p < base.row_start[std::size_t(i + 1)]; ++p)
      pattern_.column.push_back(base.column[std::size_t(p)]);
    pattern_.column.push_back(n_);
    pattern_.row_start.push_back(pattern_.nnz());
  }
  for (Index c = 0; c <= n_; ++c) pattern_.column.push_back(c);
  pattern_.row_start.push_back(pattern_.nnz());
}

void BorderedMatrix::assemble(std::span<const double> a_values, std::span<const double> column,
                              std::span<const double> row, double corner, std::span<double> values) const {
  const auto& start = pattern_.row_start;
  for (Index i = 0; i < n_; ++i) {
    const auto first = std::size_t(start[std::size_t(i)]), last = std::size_t(start[std::size_t(i + 1)]) - 1;
    std::copy(a_values.begin() + std::ptrdiff_t(first - std::size_t(i)),
              a_values.begin() + std::ptrdiff_t(last - std::size_t(i)), values.begin() + std::ptrdiff_t(first));
    values[last] = column[std::size_t(i)];
  }
  const auto bottom = std::size_t(start[std::size_t(n_)]);
  std::copy(row.begin(), row.begin() + std::ptrdiff_t(n_), values.begin() + std::ptrdiff_t(bottom));
  values[bottom + std::size_t(n_)] = corner;
}

}  // namespace twb
