// The minimally augmented system of a fold (Govaerts, "Numerical methods for
// bifurcations of dynamical equilibria", 2000), as a SteadySystem so that KINSOL's
// Newton and KLU locate the fold like any steady state (docs/physics.md section 8: distress is
// the fold of the steady branch in load).
//
// Unknowns x = (u, μ), μ = λ/λ_scale. Equations G = [F(u; λ); g(u; λ)], where the test
// function g comes from the bordered solve
//
//     [ J   b ] [ v ]   [ 0 ]
//     [ cᵀ  0 ] [ g ] = [ 1 ],
//
// and vanishes exactly where J is singular, v then spanning its null space. The borders
// only have to keep that matrix nonsingular near the fold: c not orthogonal to the null
// vector (the branch tangent's state part there), b not in the range of J. Here b = F_λ:
// at a simple fold ψᵀF_λ ≠ 0 for the left null vector ψ (that is what makes it a turning
// point rather than a branch point), so F_λ is outside range(J). b is scaled to unit
// max-norm, c so that cᵀv = ⟨t̂, v⟩ for the unit tangent t̂: then v has unit size and
// |g| = ‖J v‖∞ is in the residual's units, and one tolerance serves F and g.
//
// With w from the transposed bordered solve [Jᵀ c; bᵀ 0][w; ·] = e_{n+1},
//     ∂g/∂z = −wᵀ (∂J/∂z) v,
// i.e. ∇_u g = −(J(u+εv)ᵀw − J(u)ᵀw)/ε and ∂g/∂λ = −wᵀ(F_λ(u+εv) − F_λ(u))/ε in Newton's
// Jacobian: one-sided differences of the exact Jacobian along v from the values the
// evaluation has at u (error ~√ε_machine, far below what Newton's steps need; one
// assembly an evaluation). The fold's curvature κ takes central ones (error ~ε²).
//
// The system's own parameter is the target value of g (0 at the fold; ∂G/∂it = −e_{n+1}).
// Evaluating sets the base system's parameter to μ·λ_scale and factors the bordered
// matrix: a FoldSystem is not for concurrent use.
#pragma once

#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "solver/bordered_step.h"
#include "solver/bordered_system.h"
#include "solver/sparse_lu.h"

namespace twb {

class FoldSystem final : public BorderedSystem {
 public:
  // parameter_direction: F_λ near the fold; state_tangent: the branch tangent's state
  // part there (any scale, weighted by the metric).
  FoldSystem(SteadySystem& base, ContinuationMetric metric, std::span<const double> parameter_direction,
             std::span<const double> state_tangent);
  FoldSystem(const FoldSystem&) = delete;  // its step solver refers to its matrix
  FoldSystem& operator=(const FoldSystem&) = delete;

  // The null vector v of J at x, unit in the metric's state norm.
  std::vector<double> null_vector(std::span<const double> x) const;
  // At a fold x: the branch through it bends as λ ≈ λ* − ½κs² along u* + s·v, with
  // κ = ψᵀF_uu[v, v]/ψᵀF_λ (ψ the left null vector). κ > 0: the branch's largest λ
  // (on the bearing, distress: the cool branch ends); κ < 0: its smallest (the hot
  // branch's turning point back to the cool one); κ changes sign at a cusp. NaN where
  // the bordered matrix is singular.
  double fold_curvature(std::span<const double> x) const;
  // Both at once (one bordered factorization): the null vector, empty where the
  // bordered matrix is singular, and κ.
  std::pair<std::vector<double>, double> null_vector_and_curvature(std::span<const double> x) const;

  // The left null vector ψ of J at a fold x (ψᵀJ = 0: the transposed bordered solve's
  // w, whose last entry is g = 0 there), scaled so that ψᵀb = 1; empty where the bordered
  // matrix is singular. What a fold's load responds to: dλ*/dp = −ψᵀF_p / ψᵀF_λ.
  std::vector<double> left_null_vector(std::span<const double> x) const;

  // A singular bordered matrix (far from the fold) gives a non-finite residual, which
  // KINSOL's line search treats as a step too long.
  void evaluate(std::span<const double> x, std::span<double> residual, std::span<double> jacobian) const override;
  // Newton's steps from the bordered matrix's factors at the Jacobian's point
  // (bordered_step.h): one factorization an iteration.
  NewtonStepSolver* step_solver() const override { return step_.get(); }

 private:
  // Sets λ from x, evaluates F and J, factors the bordered matrix and solves for (v, g);
  // the factors, null when it is singular. With `for_step` they are the step solver's,
  // for the Newton step at this J; else the residual's own.
  const SparseLu* solve_bordered(std::span<const double> x, std::span<double> f, std::span<double> base_jac,
                                 std::vector<double>& vg, bool for_step = false) const;
  // The bordered solve's (v, g) as v alone, unit in the metric's state norm.
  std::vector<double> unit_null_vector(std::vector<double> vg) const;
  // J and F_λ at u, where the caller has them.
  struct AtState {
    std::span<const double> jacobian, parameter_derivative;
  };
  // ∇_u(wᵀ J v) and ∂(wᵀ J v)/∂λ by differences along v: central (error ~ε², for κ), or
  // one-sided from `at_u` (error ~ε, one assembly less: for Newton's Jacobian).
  void second_derivatives(std::span<const double> u, std::span<const double> v, std::span<const double> w,
                          std::span<double> gradient, double& parameter_part, const AtState* at_u = nullptr) const;

  std::vector<double> b_, c_;
  std::unique_ptr<SparseLu> lu_;
  std::unique_ptr<BorderedStep> step_;
};

}  // namespace twb
