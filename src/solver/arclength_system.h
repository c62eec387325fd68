// Keller's pseudo-arclength corrector as a SteadySystem, so the same KINSOL Newton and
// KLU that solve the base system correct a continuation step (docs/physics.md section 8: the
// distress fold is a turning point in λ, where continuation in λ itself must fail).
//
// Unknowns x = (u, μ), μ = λ/λ_scale (continuation_metric.h). Equations
//
//     F(u; μ·λ_scale) = 0
//     ⟨t, x − x_a⟩ − Δs = 0       (the hyperplane normal to the tangent t at the
//                                   last point x_a, a distance Δs ahead)
//
// Its Jacobian [J  λ_scale·F_λ; (ω∘t_u)ᵀ  t_μ] is nonsingular through a simple fold,
// since F_λ is not in the range of a singular J there. The same matrix with the previous
// tangent in its last row gives the new tangent, [J λ_scale·F_λ; (ω∘t_u)ᵀ t_μ]·t' = e_{n+1},
// and that row orients t' along t.
//
// The system's own parameter is the step Δs. Evaluating sets the base system's
// parameter to μ·λ_scale.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "solver/bordered_system.h"
#include "solver/sparse_lu.h"

namespace twb {

class ArclengthSystem final : public BorderedSystem {
 public:
  ArclengthSystem(SteadySystem& base, ContinuationMetric metric);

  // The hyperplane ⟨t, x − anchor⟩ = step the next correction lands on.
  void set_step(std::span<const double> anchor, std::span<const double> tangent, double step);

  // Unit tangent (in the metric) to the branch at x, a solution of F = 0, oriented so
  // that ⟨t, reference⟩ > 0. The reference is the previous tangent, or ±e_μ at the start
  // of a branch. Throws SolverFailure when the bordered matrix is singular. Given the
  // factors of that matrix at a point within a Newton step of x (the corrector's last,
  // whose last row is the reference when the reference is the step's tangent), solves
  // with them: t to O(step), as natural continuation's slope, without an assembly and a
  // factorization of its own.
  std::vector<double> tangent(std::span<const double> x, std::span<const double> reference,
                              const SparseLu* corrector_factors = nullptr);

  void evaluate(std::span<const double> x, std::span<double> residual, std::span<double> jacobian) const override;

 private:
  // F (unless residual is empty) and the bordered Jacobian (unless jacobian is empty)
  // with `row` as its last row.
  void assemble(std::span<const double> x, std::span<const double> row, std::span<double> residual,
                std::span<double> jacobian) const;

  std::vector<double> anchor_, direction_;
  std::unique_ptr<SparseLu> lu_;  // for tangents; analysed on first use
};

}  // namespace twb
