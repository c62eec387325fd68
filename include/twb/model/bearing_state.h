// What twb reports of one solved state of the bearing (docs/physics.md section 9), in SI units.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "twb/model/operating_limits.h"

namespace twb {

// Rigid-body position in physical units.
struct RigidPosition {
  double c1 = 0, gamma_x = 0, gamma_y = 0, c2 = 0;
};

// The sliding film's oil flows (m³/s, docs/physics.md section 14), from the face fluxes of
// its Reynolds balances. At a steady state with a full film supplied = leaving.
struct FilmFlows {
  double supplied = 0;  // into the film from every fed boundary: the bore and the grooves
  double inner = 0;     // leaving at the inner radius (negative: entering, as from a fed bore)
  double outer = 0;     // leaving at the outer radius
  double grooves = 0;   // out of the fed grooves into the lands and across the rims
};

// A quantity an effect reports of its own (model/reported_quantity.h): its states.csv
// column, unit in the name, and its value there.
struct ReportedValue {
  std::string column;
  double value = 0;
};

// Everything reported per solved state (docs/physics.md section 9).
struct BearingState {
  double load = 0, speed = 0;
  double washer_mean_temperature = 0;  // K, area-weighted
  double max_film_temperature = 0;     // K, hottest film node
  // K, the oil's peak: the film temperature's maximum located between the nodes
  // (docs/physics.md section 8); the ambient without the thermal effect.
  double oil_peak_temperature = 0;
  // K, the asperities' hottest contact: the faces' temperature plus Blok's flash temperature,
  // located on the sliding film (docs/physics.md section 8); none without the contact model.
  std::optional<double> contact_temperature;
  double hmin_over_sigma = 0;          // sliding film, exact minimum of its plane
  // Each body's hottest face (K), its material's temperature (docs/physics.md section 8);
  // the ambient without the thermal effect.
  double carrier_max_temperature = 0, washer_max_temperature = 0, gear_max_temperature = 0;
  double gamma_x_ratio = 0, gamma_y_ratio = 0;
  double fluid_force = 0, contact_force = 0;  // sliding film, N
  double fluid_share = 0, contact_share = 0;
  // With the gear's stop (geometry.gear.axial_play): the stop's reaction on the gear, N,
  // zero where the gear is off it (docs/physics.md section 19).
  std::optional<double> stop_reaction;
  double torque = 0, f_eff = 0;
  double stribeck = 0;  // Z N / P: Pa·s · rev/s / Pa
  double friction_coefficient = 0;
  bool friction_clamped = false;
  double heat_generated = 0, heat_to_ambient = 0, energy_error = 0;
  double force_balance_error = 0, moment_balance_error = 0;  // relative to the load
  double complementarity_error = 0;  // max |min(p̂, ŵ)|
  double max_contact_pressure = 0;   // Pa, nominal asperity pressure where either film is tightest
  std::optional<FilmFlows> flows;    // with hydrodynamics
  RigidPosition position;
  // The limits of the model and the oil this state exceeds (operating_limits.h).
  std::vector<LimitExcess> limits;
  // What the scene's effects report of their own (EffectAssembler::report), in the order
  // the effects were registered: with convection the heat the oil carries; a new effect's
  // quantities without a field here.
  std::vector<ReportedValue> reported;

  // The value an effect reported in that column; none where no effect of this state's
  // model reports it.
  std::optional<double> reported_value(std::string_view column) const {
    for (const ReportedValue& v : reported)
      if (v.column == column) return v.value;
    return std::nullopt;
  }
};

}  // namespace twb
