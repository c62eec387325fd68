// Direct solves with a sparse matrix outside Newton's loop: the tangent of a branch,
// the parameter sensitivity J·u_λ = −F_λ, the bordered systems that define a fold.
// KLU with AMD ordering, as in the Newton solver (kinsol_newton.h): the symbolic
// analysis is done once per pattern, every factor() pivots afresh, because near a fold
// the matrix is nearly singular and an old pivot order may no longer be safe.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "twb/model/sparse_assembly.h"

namespace twb {

class SparseLu {
 public:
  explicit SparseLu(const SparsePattern& pattern);
  ~SparseLu();
  SparseLu(const SparseLu&) = delete;
  SparseLu& operator=(const SparseLu&) = delete;

  // Factors the matrix with these values in the pattern's order; false when KLU finds
  // it singular (a previous factorization is then no longer available).
  bool factor(std::span<const double> values);
  // Overwrites b with A⁻¹b, or with A⁻ᵀb.
  void solve(std::span<double> b) const;
  void solve_transposed(std::span<double> b) const;
  // min/max |diag U| of the last factors (KLU's cheap rcond): tiny when nearly singular.
  double pivot_ratio() const;

 private:
  struct Klu;
  std::unique_ptr<Klu> klu_;
};

}  // namespace twb
