// The gear's stop (docs/physics.md section 19). With an axial play the gear's balance [37],
// F2 = F, becomes the complementarity of the gear's distance from its stop and the stop's
// reaction,
//
//     ŝ = (play − c1 − c2)/σ_ref ≥ 0,   R̂ = (F2 − F)/S ≥ 0,   ŝ·R̂ = 0,
//
// in the semismooth form of the film's cavitation rows: c1 + c2 is the two films' mean gap
// at the axis, the gear's height above where it would sit on the washer on the carrier.
// The rigid rows are divided by a force scale S held fixed (the scene's load), so that
// they stay rows as the load goes to zero.
#include "model/assembly_totals.h"
#include "model/bearing_model.h"
#include "model/complementarity.h"

namespace twb {

double BearingModel::force_scale() const { return gear_stop() ? scene_.operating.load : load_; }

// The gear's row holds R̂ when this is called (the films' loads and the external load
// added); its entries in c1 (the stop's, none of the films') are in the pattern from the
// structure pass on.
void BearingModel::add_gear_stop(std::span<const double> u, Assembler& a, AssemblyTotals& totals) const {
  const Index row = rigid_offset_ + 3, c1 = rigid_offset_ + 0, c2 = rigid_offset_ + 3;
  if (a.mode() != Assembler::Mode::values) {
    a.add_derivative(row, c1, 0.0);
    a.add_derivative(row, c2, 0.0);
    return;
  }
  const double gap = *scene_.gear.axial_play / sigma_ref_ - u[std::size_t(c1)] - u[std::size_t(c2)];
  const double reaction = a.residual_value(row);
  totals.stop_gap = gap;
  totals.stop_reaction = reaction;
  const Complementarity phi = complementarity(cavitation_row_, gap, reaction);
  totals.stop_reaction_slope = phi.db;
  a.set_residual(row, phi.value);
  if (!a.wants_jacobian()) return;
  a.scale_row(row, phi.db);
  a.add_derivative(row, c1, -phi.da);
  a.add_derivative(row, c2, -phi.da);
}

}  // namespace twb
