// An uncertain input in the standard normal space a reliability analysis works in
// (docs/physics.md section 17): independent inputs, each x = F⁻¹(Φ(u)) of its own
// standard normal u (the Rosenblatt transform of independent variables).
#pragma once

#include <string>

#include "twb/scene/scene.h"

namespace twb {

// Which parameters a law has: a mean and sd (normal, lognormal, truncated_normal), and
// bounds (uniform, truncated_normal).
inline bool has_mean_and_sd(InputDistribution d) { return d != InputDistribution::uniform; }
inline bool has_bounds(InputDistribution d) {
  return d == InputDistribution::uniform || d == InputDistribution::truncated_normal;
}

// x(u) in the input's SI unit.
double input_at(const UncertainInput& input, double u);
// dx/du at u: how the input moves with its standard normal variable (> 0).
double input_slope(const UncertainInput& input, double u);
// "normal(mean 0.5 mrad, sd 0.1 mrad)" style, in SI: for messages and the results.
std::string describe(const UncertainInput& input);

}  // namespace twb
