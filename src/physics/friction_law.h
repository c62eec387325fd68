// Boundary (asperity) friction coefficient, docs/physics.md section 6, paper eq [18].
#pragma once

namespace twb {

struct FrictionLawResult {
  double coefficient;  // f
  double slope;        // df/dF_cont (1/N); 0 where the force was clamped
  bool clamped;        // the force was outside the law's validity range
};

// The range of contact forces of the dry test-rig regression behind eq [18].
inline constexpr double empirical_friction_min_force = 260.5;   // N
inline constexpr double empirical_friction_max_force = 1725.6;  // N

// f = 0.48 - 0.05 ln(F), F = the film's TOTAL contact force in N, clamped to
// [260.5, 1725.6] N (f in [0.1073, 0.2017]).
FrictionLawResult empirical_friction(double total_contact_force_N);

// A given constant coefficient (the paper's Fig. 15 study): slope 0, never clamped.
FrictionLawResult constant_friction(double coefficient);

}  // namespace twb
