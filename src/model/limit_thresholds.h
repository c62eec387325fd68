// The thresholds of the limits a state can exceed (twb/model/operating_limits.h), taken
// from the scene, and the test of a state's values against them.
#pragma once

#include <vector>

#include "twb/model/operating_limits.h"
#include "twb/scene/scene.h"

namespace twb {

struct OperatingLimits {
  double max_oil_temperature = 0.0;  // K
  double flash_temperature = 0.0;    // K
  double hardness = 0.0;             // Pa, the softer face's; 0: no contact model
  double least_film = 0.5;           // h_min/σ
  bool statistical = true;           // a statistical model (contact, flow factors) is on
  static OperatingLimits of(const Scene& scene);
};

// The state's values against the limits (SI), in LimitKind order; empty when none.
struct LimitValues {
  double washer_mean_temperature = 0.0, max_film_temperature = 0.0, max_contact_pressure = 0.0;
  double hmin_over_sigma = 0.0;
  bool thermal = false;
};
std::vector<LimitExcess> exceeded_limits(const LimitValues& values, const OperatingLimits& limits);

}  // namespace twb
