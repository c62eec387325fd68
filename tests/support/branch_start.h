// A first steady state for a continuation test: KINSOL from a guess, asserted converged.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "solver/kinsol_newton.h"

namespace twb::testing {

inline std::vector<double> steady_state(SteadySystem& system, std::vector<double> guess,
                                        const NewtonSettings& settings) {
  KinsolNewton newton(system);
  const NewtonReport rep = newton.solve(guess, settings);
  EXPECT_TRUE(rep.converged) << rep.message;
  return guess;
}

}  // namespace twb::testing
