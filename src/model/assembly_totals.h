// Per-film integrals gathered while assembling, for friction (which needs the film's
// total contact force before heat can be finished) and for reporting.
#pragma once

#include <array>
#include <vector>

#include "model/bearing_model.h"

namespace twb {

// A film node's friction power's slope in the shape δ of a corner node of its cells.
struct ShapeTerm {
  int node = 0, corner = 0;
  double coefficient = 0;
};

// A film node's friction power's slope in one unknown (where the faces run in: a depth,
// through the Rq it sets, film_roughness.h).
struct DepthTerm {
  int node = 0;
  Index column = -1;
  double coefficient = 0;
};

struct FilmTotals {
  double fluid_force = 0, contact_force = 0;
  std::array<double, 3> contact_force_rigid{};  // d(contact force)/d(ĉ, γ̂x, γ̂y)
  double contact_torque_per_f = 0;              // ∫ p_c r dA: friction torque divided by f
  double viscous_torque = 0;
  double viscous_heat = 0;
  // ∫ μ V²/h̄T N_a dA per node (W): the viscous heat each node of the sliding film receives.
  std::vector<double> viscous_power;
  // ∫ p_c V N_a dA per node and its gradient in (ĉ, γ̂x, γ̂y): friction heat is f times it.
  std::vector<double> contact_power;
  std::vector<std::array<double, 3>> contact_power_rigid;
  std::vector<ShapeTerm> contact_power_shape;  // where the gap has a part only
  std::vector<DepthTerm> contact_power_depth;  // where the faces run in only
  double friction_coefficient = 0, friction_slope = 0;
  bool friction_clamped = false;
  double friction_heat = 0;
  // Flows of the sliding film (m³/s, docs/physics.md section 14): leaving it at its inner
  // and at its outer radius, and out of its fed grooves into it.
  double inner_flow = 0, outer_flow = 0, groove_flow = 0;
  // With convection: the heat the oil takes up and carries out of the film (W, docs/physics.md
  // section 15), as the heat balances hold it.
  double convected_heat = 0;
};

struct AssemblyTotals {
  std::vector<FilmTotals> film;
  // With the gear's stop (gear_stop.cpp): the gear's scaled distance from it ŝ, the scaled
  // reaction R̂ = (F2 − F)/S, and the stop row's slope in R̂.
  double stop_gap = 0, stop_reaction = 0, stop_reaction_slope = 0;
};

}  // namespace twb
