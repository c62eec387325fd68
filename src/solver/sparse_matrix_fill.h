// Writing a Jacobian held in a SparsePattern's order into a SUNDIALS CSR matrix.
#pragma once

#include <span>

#include <sundials/sundials_matrix.h>

#include "system/sparse_pattern.h"

namespace twb {

// Rewrites the whole structure and the values of J (SUNDIALS zeroes the matrix, index
// arrays included, before each Jacobian evaluation). False when a value is not finite,
// which the Jacobian callbacks report to SUNDIALS as a recoverable failure.
bool fill_sparse_matrix(SUNMatrix J, const SparsePattern& pattern, std::span<const double> values);

}  // namespace twb
