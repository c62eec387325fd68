// The slowest relaxation time of a SteadySystem's transient at a state, from its
// linearization: C·δu' = −J·δu (J = ∂F/∂u) has modes e^(−μt)·v with J·v = μ·C·v, and
// the slowest decays (or grows) at the smallest |μ|. Inverse iteration on J⁻¹C (one KLU
// factorization, a few solves) finds 1/min|μ| in the system's time units; the algebraic
// unknowns are eliminated by the solve itself.
//
// A diagonal estimate max C_k/J_kk would be wrong by orders of magnitude wherever
// conduction couples the nodes (on Bratu's grid it gives h²/2 instead of about 1/π²):
// the slowest mode is a global one.
#pragma once

#include <span>

#include "system/steady_system.h"

namespace twb {

// Throws SolverFailure when J is singular at u, std::invalid_argument when no unknown
// has a capacity.
double slowest_relaxation_time(const SteadySystem& system, std::span<const double> u, int iterations);

}  // namespace twb
