// The thresholds of the limits a state can exceed (twb/model/operating_limits.h), taken
// from the scene, and the test of a state's values against them.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "twb/model/bearing_state.h"
#include "twb/model/operating_limits.h"
#include "twb/scene/scene.h"

namespace twb {

struct OperatingLimits {
  double max_oil_temperature = 0.0;  // K
  double flash_point = 0.0;          // K, the oil's (lubricant.flash_temperature)
  double hardness = 0.0;             // Pa, the softer face's; 0: no contact model
  double least_film = 0.5;           // h_min/σ
  bool statistical = true;           // a statistical model (contact, flow factors) is on
  // Failure criteria a scene may add: each body's material limit (K; carrier, washer,
  // gear) and the least h_min/σ.
  std::array<std::optional<double>, 3> material_temperature;
  std::optional<double> min_film_ratio;
  // The washer's PV limit (Pa m/s), and what turns a state's contact force (N) and speed
  // (rad/s) into its PV: the washer's area and mean radius.
  std::optional<double> pv_limit;
  double washer_area = 0.0, mean_radius = 0.0;  // m², m
  // The critical scuffing temperature (K), where the contact model is on.
  std::optional<double> scuffing_temperature;
  // The last temperature of each body's modulus data (K; carrier, washer, gear), where its
  // material has a curve (docs/physics.md section 23).
  std::array<std::optional<double>, 3> modulus_data_end;
  static OperatingLimits of(const Scene& scene);
};


// The state's values against the limits (SI), in LimitKind order; empty when none.
struct LimitValues {
  double washer_mean_temperature = 0.0, oil_peak_temperature = 0.0, max_contact_pressure = 0.0;
  double hmin_over_sigma = 0.0;
  bool thermal = false;
  std::array<double, 3> body_temperature{};  // K: carrier, washer, gear hottest faces
  double contact_force = 0.0, speed = 0.0;   // N, the sliding film's; rad/s
  std::optional<double> contact_temperature;  // K, the asperities' hottest contact
  static LimitValues of(const BearingState& state, bool thermal);
  // The sliding face's PV: the contact force over the washer's area times the sliding
  // speed at its mean radius (docs/physics.md section 8).
  double pv(const OperatingLimits& limits) const;
};
std::vector<LimitExcess> exceeded_limits(const LimitValues& values, const OperatingLimits& limits);

// How far a state is from crossing a failure criterion, in the criterion's own unit (K,
// or h_min/σ): positive within it, zero on it, negative past it; none where the scene does
// not apply the criterion (no thermal effect, no material limit, no least film).
std::optional<double> failure_margin(LimitKind kind, const LimitValues& values, const OperatingLimits& limits);
// Whether the scene applies a criterion at all: its margin exists for some state.
bool criterion_applies(LimitKind kind, const OperatingLimits& limits, bool thermal);

}  // namespace twb
