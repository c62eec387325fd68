// Newton's step for a bordered Jacobian A = [J a; dᵀ δ] (the minimally augmented fold
// system's: fold_system.h) from the factors of M = [J b; cᵀ 0] at the same J, the matrix
// whose solve gives the fold's test function and which is factored at every evaluation
// anyway. A differs from M in its last row and column only, a change of rank two, so
// (Sherman–Morrison–Woodbury)
//
//     A_s⁻¹r = M⁻¹r − Z C⁻¹ Vᵀ M⁻¹r,   Z = M⁻¹U,   C = I + VᵀZ,
//     U = [(σa − b; 0), e],   V = [e, (ρd − c; ρσδ)],
//
// for A_s = R A S, whose last column is scaled by σ = |b|/|a| and last row by ρ = |c|/|d|
// (max-norms): then neither change dwarfs M and the formula loses no digits to
// cancellation. A is regular at a regular fold and M near it, so C is. One factorization
// a Newton iteration instead of two (M's, then A's with its dense row).
#pragma once

#include <span>
#include <vector>

#include "solver/bordered_matrix.h"
#include "solver/sparse_lu.h"
#include "system/newton_step_solver.h"

namespace twb {

class BorderedStep final : public NewtonStepSolver {
 public:
  // b, c: M's border column and row (length n); matrix: the pattern of M and A.
  BorderedStep(const BorderedMatrix& matrix, std::vector<double> b, std::vector<double> c);

  // M factored from J's values (the base pattern's order), for the evaluation that
  // assembles A at the same J: its setup() then factors nothing. False where M is
  // singular.
  bool factor(std::span<const double> base_jacobian);
  // The factors of M at the last factor() (or setup(), where it had to factor again).
  const SparseLu& factors() const { return lu_; }

  bool setup(std::span<const double> values) override;
  bool solve(std::span<double> rhs) override;

 private:
  // M's values from A's (the same J), into `m`.
  void border(std::span<const double> a_values, std::vector<double>& m) const;
  // Factors M with values m unless it already holds them.
  bool hold(const std::vector<double>& m);

  const BorderedMatrix& matrix_;
  std::vector<double> b_, c_;
  SparseLu lu_;
  std::vector<double> held_;   // M's values in lu_ (empty: none)
  std::vector<double> setup_;  // M's values at the last setup
  // The last setup's Woodbury terms: Z's columns, V's second, C⁻¹, the scales.
  std::vector<double> z1_, z2_, q_;
  double inverse_[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  double sigma_ = 1.0, rho_ = 1.0;
  bool ready_ = false;
};

}  // namespace twb
