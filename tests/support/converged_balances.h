// What a converged state of the bearing promises (issue contract): force and moment
// balance to 1e-8 of the load and the energy balance to 1e-8 of the heat generated.
// The solver's tolerance is 1e-10 on the scaled residual (forces over the load, heat
// rows in kelvin over a node conductance), which bounds the balances well inside 1e-8.
#pragma once

#include <gtest/gtest.h>

#include "model/bearing_model.h"

namespace twb::testing {

inline void expect_balanced(const BearingState& s) {
  EXPECT_LT(s.force_balance_error, 1e-8);
  EXPECT_LT(s.moment_balance_error, 1e-8);
  EXPECT_LT(s.energy_error, 1e-8);
}

}  // namespace twb::testing
