#include "solver/pattern_klu.h"

#include <span>

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

namespace twb {

PatternKlu& pattern_klu(SUNLinearSolver s) { return *static_cast<PatternKlu*>(s->content); }

namespace {

// guarded_callback's −1 (it stopped an exception) as the linear solver's flag for it.
int unrecoverable_if_thrown(int flag) { return flag < 0 ? SUNLS_PACKAGE_FAIL_UNREC : flag; }

}  // namespace

SUNLinearSolver make_pattern_klu(SUNContext ctx, const SparsePattern& pattern, SparseLu::Ordering ordering,
                                 NewtonStepSolver* own) {
  SUNLinearSolver s = SUNLinSolNewEmpty(ctx);
  if (!s) return nullptr;
  try {
    s->content = new PatternKlu(pattern, ordering, own);
  } catch (...) {
    SUNLinSolFreeEmpty(s);
    throw;
  }
  s->ops->gettype = [](SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; };
  s->ops->getid = [](SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; };
  // KINSol initializes its linear solver at every call: the analysis stays valid.
  s->ops->initialize = [](SUNLinearSolver) { return SUNLS_SUCCESS; };
  // A singular matrix is recoverable: KINSOL reports it, the caller's globalization
  // (pseudo-time, ramps) moves on.
  // Nothing may be thrown into KINSOL: anything that is (an allocation failing) ends
  // the solve as unrecoverable.
  s->ops->setup = [](SUNLinearSolver ls, SUNMatrix a) {
    PatternKlu& k = pattern_klu(ls);
    return k.last_flag = unrecoverable_if_thrown(guarded_callback(k.failure, [&] {
             const std::span<const double> values(SUNSparseMatrix_Data(a), std::size_t(SUNSparseMatrix_NNZ(a)));
             k.ready = k.own ? k.own->setup(values) : k.lu->refactor(values);
             return k.ready ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_REC;
           }));
  };
  s->ops->solve = [](SUNLinearSolver ls, SUNMatrix, N_Vector x, N_Vector b, realtype) {
    PatternKlu& k = pattern_klu(ls);
    if (k.own ? !k.ready : !k.lu->factored()) return k.last_flag = SUNLS_PACKAGE_FAIL_REC;
    return k.last_flag = unrecoverable_if_thrown(guarded_callback(k.failure, [&] {
             N_VScale(1.0, b, x);
             const std::span<double> rhs(N_VGetArrayPointer(x), std::size_t(N_VGetLength(x)));
             if (k.own) return k.own->solve(rhs) ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_REC;
             k.lu->solve(rhs);
             return SUNLS_SUCCESS;
           }));
  };
  s->ops->lastflag = [](SUNLinearSolver ls) { return sunindextype(pattern_klu(ls).last_flag); };
  s->ops->free = [](SUNLinearSolver ls) {
    if (!ls) return SUNLS_SUCCESS;
    delete static_cast<PatternKlu*>(ls->content);
    ls->content = nullptr;
    SUNLinSolFreeEmpty(ls);
    return SUNLS_SUCCESS;
  };
  return s;
}

}  // namespace twb
