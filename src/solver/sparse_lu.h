// Direct solves with a sparse matrix of fixed pattern, by KLU with AMD ordering (on
// A + Aᵀ: dense rigid-body or bordering rows and columns are ordered last; COLAMD,
// SUNDIALS' default, fills the bearing's arrow-shaped Jacobian about six-fold), and
// above kNestedDissectionAbove unknowns with nested dissection (nested_dissection.h),
// whose factors grow more slowly with the mesh. The symbolic analysis is done once per
// pattern. Two ways to factor:
//  - factor() pivots afresh every time: for the first tangent of a branch and the
//    parameter sensitivity J·u_λ = −F_λ, where the matrix is nearly singular and an old
//    pivot order may no longer be safe;
//  - refactor() reuses the pivot sequence of the last full factorization while that is
//    safe: for the Jacobians of successive Newton and pseudo-time steps (KINSOL's
//    linear solver in kinsol_newton.cpp, the pseudo-time stepper in pseudo_transient.cpp)
//    and the bordered matrix of the fold system, which stays regular at the fold
//    (fold_system.h; refactoring it left the bearing's fold curve unchanged to 10 digits
//    and cut its time by 12 %).
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "system/sparse_pattern.h"

namespace twb {

class SparseLu {
 public:
  // Nested dissection's refactorization beats AMD's from the 17×132 mesh on (8750
  // unknowns: 6.2 against 8.6 ms; 615 against 1254 ms on 65×528) and ties below
  // (benchmarks/README.md, "Linear solvers"); the paper's mesh keeps AMD.
  static constexpr Index kNestedDissectionAbove = 5000;
  // by_size: nested dissection above kNestedDissectionAbove or where the pattern prefers
  // it (SparsePattern::prefers_nested_dissection), else AMD. minimum_degree:
  // AMD at any size, for a solver that factors a few times only (a state refined once
  // for its error bar: METIS's order costs about 80 ms on 17×132, a dozen of its
  // refactorizations' saving; nested_dissection.cpp keeps the orders it found).
  enum class Ordering { by_size, minimum_degree };
  explicit SparseLu(const SparsePattern& pattern, Ordering ordering = Ordering::by_size);
  ~SparseLu();
  SparseLu(const SparseLu&) = delete;
  SparseLu& operator=(const SparseLu&) = delete;

  // Factors the matrix with these values in the pattern's order, with fresh partial
  // pivoting; false when KLU finds it singular (a previous factorization is then no
  // longer available).
  bool factor(std::span<const double> values);
  // Factors the matrix with the pivot sequence of the last full factorization, and
  // pivots afresh as factor() does when there is none, when that sequence meets a zero
  // pivot, or when its reciprocal pivot growth falls below 1/100 of the full
  // factorization's (LU's backward error grows with the pivot growth: 100× the growth
  // fresh pivots gave still leaves a Newton direction accurate to ~1e-13). False when
  // the matrix is singular.
  bool refactor(std::span<const double> values);
  bool factored() const;
  // Overwrites b with A⁻¹b, or with A⁻ᵀb.
  void solve(std::span<double> b) const;
  void solve_transposed(std::span<double> b) const;
  // min/max |diag U| of the last factors (KLU's cheap rcond): tiny when nearly singular.
  double pivot_ratio() const;

  // KLU's work so far (diagnostics: TWB_KINSOL_PRINT).
  struct Counts {
    long analyses = 0, factorizations = 0, refactorizations = 0;
    // Numeric factorizations, full or reusing a pivot sequence, since `earlier`.
    long factored_since(const Counts& earlier) const {
      return factorizations - earlier.factorizations + refactorizations - earlier.refactorizations;
    }
  };
  const Counts& counts() const;
  // The entries of the last factorization's L and U (KLU's lnz + unz), 0 before one: its fill.
  long factor_entries() const;
  // The same over every SparseLu of the calling thread since it started.
  static const Counts& thread_counts();

 private:
  struct Klu;
  std::unique_ptr<Klu> klu_;
};

}  // namespace twb
