#include "physics/friction_law.h"

#include <cmath>

namespace twb {

FrictionLawResult empirical_friction(double total_contact_force_N) {
  // Eq [18] is a regression of dry test-rig data, valid only in its load range
  // (docs/physics.md section 6): outside it the force is clamped and the caller told so.
  double force = total_contact_force_N;
  bool clamped = false;
  if (force < empirical_friction_min_force) {
    force = empirical_friction_min_force;
    clamped = true;
  } else if (force > empirical_friction_max_force) {
    force = empirical_friction_max_force;
    clamped = true;
  }
  return {0.48 - 0.05 * std::log(force), clamped ? 0.0 : -0.05 / force, clamped};
}

FrictionLawResult constant_friction(double coefficient) {
  return {coefficient, 0.0, false};
}

}  // namespace twb
