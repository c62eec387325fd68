// Is a steady state stable? The linearized transient C·δu' = −J·δu (steady_system.h)
// has modes e^(−μt)·v with J·v = μ·C·v; the state is stable when every μ has Re μ > 0.
// The algebraic unknowns (C_k = 0) are eliminated by a solve with J itself: for x on the
// differential unknowns, the differential part of J⁻¹(C·x) is S⁻¹C_d·x with S the Schur
// complement of J onto them, whose eigenvalues are exactly 1/μ over the finite modes.
//
// Shift-invert Arnoldi (shift 0) on that operator, with the factors of J a Newton
// corrector already holds, brings out the modes of smallest |μ| first: the slow ones, and
// among them the one that crosses zero at a fold of the branch. A state is judged
//   stable         when the slowest modes are resolved and all have Re μ > 0 by a margin
//                  well above their own error;
//   unstable       when a resolved mode has Re μ < 0 by that margin;
//   inconclusive   otherwise (unresolved modes, or one within its error of the
//                  imaginary axis): the caller asks the transient.
// What it cannot see is a mode with |μ| beyond the resolved ones crossing the imaginary
// axis far from the origin (a fast oscillatory instability). A branch continued from a
// state the transient proved stable can only lose stability through a crossing, and a
// real crossing (the bearing's thermal folds) passes through the origin, where this test
// looks first.
#pragma once

#include <complex>
#include <span>
#include <string>
#include <vector>

#include "solver/sparse_lu.h"
#include "system/steady_system.h"

namespace twb {

struct StabilitySettings {
  // Krylov dimension: at most this many solves with J. The bearing's slowest modes are a
  // few thermal ones well separated from the fast conduction modes, so 24 resolves the
  // slowest half dozen to a relative residual far below the margin.
  int krylov_dimension = 24;
  // A Ritz value counts as resolved when its residual is below this fraction of the
  // dominant |1/μ|; with the margin below this leaves a factor 100 between a mode's error
  // and the distance from the axis that decides.
  double resolved = 1e-8;
  // A resolved mode decides when |Re μ| exceeds this fraction of |μ|.
  double margin = 1e-6;
  // How many of the slowest modes must be resolved for a stable verdict.
  int required_modes = 3;
};

enum class Stability { stable, unstable, inconclusive };
const char* to_string(Stability s);

struct StabilityReport {
  Stability verdict = Stability::inconclusive;
  std::vector<std::complex<double>> modes;  // resolved μ, slowest first (time⁻¹ of the system)
  int solves = 0;                           // solves with J
  std::string reason;
  // The rightmost resolved mode's −Re μ (the growth rate; negative when stable), if any.
  double growth_rate() const;
};

// factors: J at u (or within a Newton step of it). Throws std::invalid_argument when no
// unknown has a capacity.
StabilityReport linear_stability(const SteadySystem& system, const SparseLu& factors,
                                 const StabilitySettings& settings = {});

}  // namespace twb
