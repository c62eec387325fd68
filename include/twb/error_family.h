// The errors a twb run ends with, one family, each with its exit status and whose
// fault it is (docs/reliability.md, "Errors"):
//   2  input     what the user gave is wrong: a scene (InputError, twb/input_error.h,
//                located), a command-line value or an argument of the API
//                (std::invalid_argument)
//   3  solver    a state the run needs could not be solved (SolverFailure,
//                twb/solver_failure.h), in the physics' words where twb knows them
//   4  internal  a precondition inside twb broke (InternalError, and anything else
//                thrown): a bug, to be reported
//   5  io        an input or output failed (IoError, std::filesystem::filesystem_error):
//                a file that cannot be written, an MPI call that fails; the system's
//                fault or the machine's, said as the system says it
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

// An input or output the system refused: neither the user's input nor a bug in twb, so
// its message names what failed and the system's reason instead of asking for a report.
class IoError : public std::runtime_error {
 public:
  // "{failed} '{path}': {the system's words for error_number}", e.g. "cannot write
  // 'out/states.csv': No space left on device"; error_number is an errno value.
  IoError(const std::string& failed, const std::string& path, int error_number);
  // A failure with no file and no errno (an MPI call), said whole.
  explicit IoError(const std::string& what);

  const std::string& path() const { return path_; }  // empty for none
  int error_number() const { return error_number_; }   // 0 for none

 private:
  std::string path_;
  int error_number_ = 0;
};

enum class ErrorKind { input = 2, solver = 3, internal = 4, io = 5 };

struct ErrorReport {
  ErrorKind kind = ErrorKind::internal;
  std::string message;  // for stderr: what, and for internal errors the request to report it
  int exit_status() const { return int(kind); }
};

// The report of a thrown error (std::current_exception() in a catch (...)).
ErrorReport report_error(std::exception_ptr error);

}  // namespace twb
