// The C boundary of a SUNDIALS callback: nothing may be thrown into KINSOL or IDA. An
// exception is kept (its message for the solver's report; an InternalError itself, which
// the solver throws again once SUNDIALS has returned: a bug is never turned into a failed
// solve) and the callback returns −1, unrecoverable to SUNDIALS.
#pragma once

#include <exception>
#include <string>
#include <utility>

#include "twb/error_family.h"

namespace twb {

// What a callback kept of the exception it stopped.
struct CallbackFailure {
  std::string message;          // what it threw, for the report
  std::exception_ptr internal;  // an InternalError, to throw again after the solve
  // Once the C solver has returned: the internal error, if one was kept, thrown again.
  void rethrow_internal() {
    if (internal) std::rethrow_exception(std::exchange(internal, nullptr));
  }
};

// body() returns the callback's flag (0, or > 0 for a recoverable failure).
template <class Body>
int guarded_callback(CallbackFailure& failure, const Body& body) noexcept {
  try {
    try {
      return body();
    } catch (const InternalError& e) {
      failure.message = e.what();
      failure.internal = std::current_exception();
    } catch (const std::exception& e) {
      failure.message = e.what();
    } catch (...) {
      failure.message = "an exception of unknown type";
    }
  } catch (...) {
    // Not even the message could be kept (no memory): the flag still fails the solve.
  }
  return -1;
}

}  // namespace twb
