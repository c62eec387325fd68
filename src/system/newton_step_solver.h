// Newton's linear solve done by a system itself, from factors it already holds (the fold
// system's, from the bordered matrix whose solve gives its test function: bordered_step.h
// in solver/). KINSOL's linear solver then calls it instead of factoring the Jacobian as
// assembled.
#pragma once

#include <span>

namespace twb {

class NewtonStepSolver {
 public:
  virtual ~NewtonStepSolver() = default;
  // Ready to solve with the Jacobian `values` (the system's pattern order); false where
  // it is singular.
  virtual bool setup(std::span<const double> values) = 0;
  // rhs ← J⁻¹ rhs, J the last setup's Jacobian; false where that can no longer be done.
  virtual bool solve(std::span<double> rhs) = 0;
};

}  // namespace twb
