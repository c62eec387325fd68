// Holds a system's continuation parameter (the bearing's load) for a scope: whatever
// the solvers inside set it to, the system leaves the scope at the value it entered
// with. A study takes one at its entry, so that its caller's model is the model it gave.
#pragma once

#include "system/steady_system.h"

namespace twb {

class ParameterScope {
 public:
  explicit ParameterScope(SteadySystem& system) : system_(system), entered_(system.parameter()) {}
  ParameterScope(SteadySystem& system, double value) : ParameterScope(system) { system.set_parameter(value); }
  // The value was the system's own when the scope began, so setting it back cannot fail.
  ~ParameterScope() { system_.set_parameter(entered_); }
  ParameterScope(const ParameterScope&) = delete;
  ParameterScope& operator=(const ParameterScope&) = delete;

 private:
  SteadySystem& system_;
  double entered_;
};

}  // namespace twb
