// A steady state of any SteadySystem at its current parameter, from a start: Newton
// first (a short budget) and, when it fails or is not asked for, pseudo-transient
// continuation (Kelley & Keyes' ΨTC), whose steps become Newton's as the pseudo-time
// step grows. The generic loop: what to do when even this fails (ramps, mesh
// sequences, homotopies) is the bearing's and lives with the studies
// (study/steady_solver.h).
#pragma once

#include <string>
#include <vector>

#include "solver/kinsol_newton.h"
#include "system/steady_system.h"

namespace twb {

struct SteadyReport {
  bool converged = false;
  std::string strategy;  // "newton", "pseudo-transient", "speed ramp", "load ramp"
  int newton_solves = 0;
  long iterations = 0, jacobian_evaluations = 0, residual_evaluations = 0;
  double residual_norm = 0.0;
  double wall_ms = 0.0;
  std::string message;
  // What each strategy that failed before the reported one said (solve_cold), in order:
  // kept, so that a cause is never lost; a failed cold start's message ends with them.
  std::vector<std::string> attempts;
};

class PseudoTransient {
 public:
  // newton: the Newton solver of the same system, whose factorization the pseudo-time
  // steps share (one analysis per solver, not per start).
  PseudoTransient(SteadySystem& system, const NewtonSettings& settings, KinsolNewton& newton)
      : system_(system), settings_(settings), newton_(newton) {}

  // Newton (if newton_first), then pseudo-transient continuation from u; true when u
  // is now a steady state. Counted into rep.
  bool reach(std::vector<double>& u, SteadyReport& rep, bool newton_first = true) const;
  // KINSOL's Newton from u on the system's Newton form (SteadySystem::set_newton_form),
  // its own form restored afterwards; counted into rep.
  bool newton(std::vector<double>& u, const NewtonSettings& s, SteadyReport& rep) const;

 private:
  SteadySystem& system_;
  NewtonSettings settings_;
  KinsolNewton& newton_;
};

}  // namespace twb
