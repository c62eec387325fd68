#include "solver/sundials_context.h"

namespace twb {

void SundialsContextDeleter::operator()(SUNContext c) const { SUNContext_Free(&c); }

SundialsContext make_context() {
  SUNContext ctx = nullptr;
  if (SUNContext_Create(nullptr, &ctx) != 0 || !ctx) throw SolverFailure("SUNContext_Create failed", -1);
  return SundialsContext(ctx);
}

void check_flag(int flag, const char* call) {
  if (flag < 0) throw SolverFailure(std::string(call) + " failed", flag);
}

}  // namespace twb
