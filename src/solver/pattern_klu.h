// KINSOL's linear solver: SparseLu on the system's pattern, which is fixed for the
// system's life (SteadySystem::pattern()). SUNDIALS' own KLU module redoes the symbolic
// analysis and a full pivoting factorization at the start of every KINSol call; here
// the analysis is done once per solver, and every later Jacobian is refactored with the
// pivot sequence of the last full factorization while that is safe
// (SparseLu::refactor). The matrix KINSOL hands over is the CSR matrix of that pattern
// (fill_sparse_matrix), in the pattern's order.
#pragma once

#include <optional>

#include <sundials/sundials_linearsolver.h>

#include "solver/callback_guard.h"
#include "solver/sparse_lu.h"
#include "system/newton_step_solver.h"

namespace twb {

struct PatternKlu {
  // own: the system's own step solver (newton_step_solver.h), which then does every
  // setup and solve; null: SparseLu on the pattern.
  PatternKlu(const SparsePattern& pattern, SparseLu::Ordering ordering, NewtonStepSolver* own_solver)
      : own(own_solver) {
    if (!own) lu.emplace(pattern, ordering);
  }
  NewtonStepSolver* own = nullptr;
  std::optional<SparseLu> lu;
  bool ready = false;  // the own solver's last setup succeeded
  int last_flag = SUNLS_SUCCESS;
  // What setup or solve threw (callback_guard.h): KINSOL sees an unrecoverable failure,
  // and the Newton solver throws an internal error again once KINSOL has returned.
  CallbackFailure failure;
};

// The solver's own factorization (shared with the pseudo-time steps).
PatternKlu& pattern_klu(SUNLinearSolver s);
// A SUNLinearSolver whose every operation catches everything (nothing may be thrown into
// KINSOL); null where SUNDIALS cannot allocate one. Freed by SUNLinSolFree. With
// `own`, the system's step solver does the work.
SUNLinearSolver make_pattern_klu(SUNContext ctx, const SparsePattern& pattern, SparseLu::Ordering ordering,
                                 NewtonStepSolver* own = nullptr);

}  // namespace twb
