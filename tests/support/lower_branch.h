// A model problem's steady state on the branch that starts at u = 0, λ = 0 (the
// stable, lower branch of Semenov and Bratu), by natural continuation: Newton at
// λ_i = λ·i/steps warm-started from the state at λ_(i−1).
#pragma once

#include <stdexcept>
#include <vector>

#include "solver/kinsol_newton.h"

namespace twb::testing {

inline std::vector<double> lower_branch_state(SteadySystem& system, double lambda, int steps = 10) {
  std::vector<double> u(std::size_t(system.size()), 0.0);
  KinsolNewton newton(system);
  for (int i = 0; i <= steps; ++i) {
    system.set_parameter(lambda * double(i) / double(steps));
    if (!newton.solve(u, NewtonSettings{}).converged) throw std::runtime_error("lower branch: Newton failed");
  }
  return u;
}

}  // namespace twb::testing
