// RAII ownership of the SUNDIALS objects twb uses, so that no path leaks them.
#pragma once

#include <memory>
#include <string>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "twb/solver_failure.h"

namespace twb {

struct SundialsContextDeleter { void operator()(SUNContext c) const; };
struct NVectorDeleter { void operator()(N_Vector v) const { N_VDestroy(v); } };
struct MatrixDeleter { void operator()(SUNMatrix m) const { SUNMatDestroy(m); } };
struct LinearSolverDeleter { void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); } };

using SundialsContext = std::unique_ptr<std::remove_pointer_t<SUNContext>, SundialsContextDeleter>;
using Vector = std::unique_ptr<std::remove_pointer_t<N_Vector>, NVectorDeleter>;
using Matrix = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;
using LinearSolver = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LinearSolverDeleter>;
// A KINSOL or IDA solver's memory, owned from its creation: a set-up call that throws
// in a constructor frees it too. Declared after the linear solver, matrix and vectors
// it uses, so that it is freed before them.
struct KinsolDeleter { void operator()(void* memory) const; };
struct IdaDeleter { void operator()(void* memory) const; };
using KinsolMemory = std::unique_ptr<void, KinsolDeleter>;
using IdaMemory = std::unique_ptr<void, IdaDeleter>;

SundialsContext make_context();

// For set-up calls, which fail only on a programming error: throws InternalError
// (twb/error_family.h) naming the call when flag < 0.
void check_flag(int flag, const char* call);

}  // namespace twb
