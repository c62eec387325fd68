// The error a run ends with when a state it needs cannot be solved (exit status 3 of
// the twb command); scene errors are twb::InputError (twb/input_error.h).
#pragma once

#include <stdexcept>
#include <string>

namespace twb {

// Thrown when a SUNDIALS solver fails; carries the solver's own message.
class SolverFailure : public std::runtime_error {
 public:
  SolverFailure(const std::string& what, int flag) : std::runtime_error(what), flag_(flag) {}
  int flag() const { return flag_; }

 private:
  int flag_;
};

}  // namespace twb
