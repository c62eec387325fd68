// The errors a twb run ends with, one family, each with its exit status and whose
// fault it is (docs/reliability.md, "Errors"):
//   2  input     what the user gave is wrong: a scene (InputError, twb/input_error.h,
//                located), a command-line value or an argument of the API
//                (std::invalid_argument)
//   3  solver    a state the run needs could not be solved (SolverFailure,
//                twb/solver_failure.h), in the physics' words where twb knows them
//   4  internal  a precondition inside twb broke (InternalError, and anything else
//                thrown): a bug, to be reported
// The family is the base layer's (docs/architecture.md): every other layer throws it.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

namespace twb {

// A broken precondition of twb's own code (arrays of another size, a rule that does not
// exist): never the user's input, which is checked where it is read.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

enum class ErrorKind { input = 2, solver = 3, internal = 4 };

struct ErrorReport {
  ErrorKind kind = ErrorKind::internal;
  std::string message;  // for stderr: what, and for internal errors the request to report it
  int exit_status() const { return int(kind); }
};

// The report of a thrown error (std::current_exception() in a catch (...)).
ErrorReport report_error(std::exception_ptr error);

}  // namespace twb
