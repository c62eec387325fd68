#include "solver/sundials_context.h"

#include <fmt/format.h>
#include <idas/idas.h>  // IDA with quadratures (a duty cycle's heat integrals)
#include <kinsol/kinsol.h>

#include "twb/error_family.h"

namespace twb {

void SundialsContextDeleter::operator()(SUNContext c) const { SUNContext_Free(&c); }
void KinsolDeleter::operator()(void* memory) const { KINFree(&memory); }
void IdaDeleter::operator()(void* memory) const { IDAFree(&memory); }

SundialsContext make_context() {
  SUNContext ctx = nullptr;
  if (SUNContext_Create(nullptr, &ctx) != 0 || !ctx) throw SolverFailure("SUNContext_Create failed", -1);
  return SundialsContext(ctx);
}

void check_flag(int flag, const char* call) {
  if (flag < 0) throw InternalError(fmt::format("{} failed (SUNDIALS flag {})", call, flag));
}

}  // namespace twb
