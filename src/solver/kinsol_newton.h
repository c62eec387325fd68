// Newton's method on a SteadySystem (the bearing, or any other) with SUNDIALS KINSOL:
// without a pseudo-time shift a few full steps first, then line search globalization;
// the system's exact sparse Jacobian in CSR, one assembly per point serving KINSOL's
// residual and Jacobian; factored by KLU through SparseLu (symbolic analysis once per
// solver, later Jacobians refactored with the last pivot sequence, pivoted afresh on a
// zero pivot or large pivot growth: sparse_lu.h), or by the system itself where it
// holds the factors (SteadySystem::step_solver: the fold system's).
#pragma once

#include <cmath>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "solver/sparse_lu.h"
#include "system/steady_system.h"
#include "solver/sundials_context.h"

namespace twb {

struct NewtonSettings {
  double residual_tolerance = 1e-10;  // max-norm of the scaled residual
  double step_tolerance = 1e-14;
  int max_iterations = 200;
  double max_step = 20.0;  // largest rigid-body move per Newton step, in units of σ (and γ_ref)
  // False: undamped steps only, no line search after them. For starts that belong in
  // Newton's quadratic basin (a continuation's prediction, a trajectory slowed near a
  // steady state): there a solve converges in a few full steps, and a failure, which
  // the line search would stretch to max_iterations more, only tells the caller to
  // shorten the step or to wait.
  bool line_search = true;
  // Newton iterations one Jacobian serves (KINSetMaxSetupCalls): 1 is Newton's method,
  // more a chord method between refactorizations. 1 by default: quadratic convergence is
  // worth one assembly and KLU refactorization per iteration on this system
  // (benchmarks/jacobian_reuse).
  int jacobian_reuse = 1;
  // A caller that needs one unknown only, and to a known accuracy (a fold's load on the
  // refined mesh, for an error bar): Newton stops at the first point that its step moved
  // by at most `watched_step` in unknown `watched` and whose residual is within
  // `watched_residual`, although the residual is not yet within residual_tolerance.
  // Past the first steps Newton's error contracts at least by half a step here (its
  // linear stretches, across the kinks of contact and cavitation, contract by a factor
  // of 2 to 3; otherwise it is quadratic), so that unknown is then within about one
  // step of the root. -1: off.
  Index watched = -1;
  double watched_step = 0.0;
  double watched_residual = 1e-3;
  // The same for a caller that needs quantities of the state to a known accuracy (a
  // state's reported quantities on the refined mesh, for their error bars): at each
  // Newton point past the start of the undamped steps (KINSOL's first full steps, whose
  // points are consecutive iterates), before it is assembled, `quantities.at(u)`; Newton
  // stops at the first point where `quantities.settled(reads)` says it is close enough
  // to the root, from every read of this solve so far and the residual's last
  // contraction. That point is returned unassembled (the report's residual_norm is
  // NaN). Not on a pseudo-time step's solve.
  struct QuantityReads {
    std::vector<std::vector<double>> values;  // at the Newton points read, the last one now
    // ‖F‖∞ at the last Newton point assembled over that at the one before (NaN before
    // two): the contraction of the step before the last one read.
    double residual_contraction = NAN;
  };
  struct WatchedQuantities {
    std::function<std::vector<double>(std::span<const double>)> at;
    std::function<bool(const QuantityReads&)> settled;
  };
  WatchedQuantities quantities{};
};

// Whether the quantities read are within `within(k, value)` of the root's, by the
// contraction's bound (the fixed-point theorem's a-posteriori bound): with the error
// falling by at least ρ < 1 a step from here on, that of point k is at most ρ/(1 − ρ)
// times the step from point k − 1 to it. ρ is the largest contraction seen over the
// last steps (each quantity's last step over the one before, and the residual's):
// Newton's converges faster after (quadratically, or by about the same factor on its
// linear stretches across the kinks of contact and cavitation). False before three
// reads (two steps give a contraction) or while not contracting.
bool settled_by_contraction(const NewtonSettings::QuantityReads& reads,
                            const std::function<double(std::size_t, double)>& within);

struct NewtonReport {
  bool converged = false;
  int flag = 0;
  long iterations = 0;
  long residual_evaluations = 0;
  long jacobian_evaluations = 0;
  long backtracks = 0;
  double residual_norm = 0.0;  // max-norm of the scaled residual at the returned state (NaN: see quantities)
  bool watched_settled = false;  // converged by the watched unknown's step (NewtonSettings::watched)
  std::string worst_block;     // where the residual is largest, when not converged
  Index worst_row = -1;
  std::string message;
};

// A pseudo-time shift: solve F(u) + (u − anchor)/Δτ = 0 instead of F(u) = 0, i.e. one
// implicit Euler step of u' = −F(u) in the scaled unknowns (pseudo-transient
// continuation). Large Δτ recovers Newton; small Δτ makes the system diagonally
// dominant and Newton's basin large.
struct PseudoTimeShift {
  double inverse_step = 0.0;  // 1/Δτ
  std::vector<double> anchor;
  // Per-unknown weights (e.g. |∂F_k/∂u_k|), so every unknown relaxes at the same rate
  // in pseudo-time; empty means 1.
  std::vector<double> weight;
  double coefficient(std::size_t k) const { return inverse_step * (weight.empty() ? 1.0 : weight[k]); }
};

class KinsolNewton {
 public:
  // ordering: the linear solver's (sparse_lu.h); by size unless the solver factors a few
  // times only.
  explicit KinsolNewton(const SteadySystem& system, SparseLu::Ordering ordering = SparseLu::Ordering::by_size);
  ~KinsolNewton();
  KinsolNewton(const KinsolNewton&) = delete;
  KinsolNewton& operator=(const KinsolNewton&) = delete;

  // Solves in place from u; u holds the final iterate even when the report says it did
  // not converge. Never throws on non-convergence.
  NewtonReport solve(std::vector<double>& u, const NewtonSettings& settings,
                     const PseudoTimeShift* shift = nullptr);

  const SteadySystem& system() const { return model_; }
  // KINSOL's linear solver: the system's pattern analysed once. Other solves with the
  // system's Jacobian (a continuation's tangent) may factor into it between Newton
  // solves; KINSOL sets its own Jacobian up again at every iteration. Not for a system
  // that solves its own Newton steps.
  SparseLu& factorization();
  // Callback state, public for the C trampolines.
  struct Callbacks;

 private:
  // True when every row of residual r at y is within the tolerance plus its own
  // rounding floor (solve(): a stall at machine precision is convergence).
  bool within_rounding(std::span<const double> y, std::span<const double> r, double tolerance) const;

  const SteadySystem& model_;
  SundialsContext ctx_;
  Vector y_, scale_, residual_scale_;
  Matrix jac_;
  LinearSolver klu_;
  KinsolMemory kin_;
  std::unique_ptr<Callbacks> callbacks_;
};

double max_norm(std::span<const double> v);

}  // namespace twb
