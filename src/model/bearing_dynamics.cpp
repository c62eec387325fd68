// The bearing as a parametrized system with a pseudo-time transient (steady_system.h).
#include <algorithm>
#include <stdexcept>

#include "model/assembly_totals.h"
#include "model/bearing_model.h"
#include "twb/error_family.h"

namespace twb {

// Only the 4 rigid-body rows see the load (without the gear's stop; with it, below, the
// gear's row alone): after orientation
//   F_k = −(S_k / ref_k − δ_k3),   ref = W (forces) or W·r_o (moments)   (eqs [34]-[37]),
// with S_k the film sums, which do not depend on W. Hence
//   ∂F_k/∂W = S_k / (ref_k · W) = (δ_k3 − F_k) / W,
// exact from the residual at u.
void BearingModel::parameter_derivative(std::span<const double> u, std::span<double> derivative) const {
  if (derivative.size() != u.size()) throw InternalError("parameter_derivative: size mismatch");
  std::vector<double> r(u.size());
  evaluate(u, r, {});
  parameter_derivative_given(u, r, derivative);
}

// The load enters only the four rigid rows, the force and moment balances divided by W:
// r_k = δ_k3 − G_k(u)/W (F_ext/W = 1 in the axial force row), so ∂r_k/∂W = G_k/W² =
// (δ_k3 − r_k)/W from the residual alone.
//
// With the gear's stop the rows are divided by a fixed S: the moments and the washer's
// force do not see the load, and the gear's row −φ(ŝ, R̂), R̂ = (F2 − W)/S, has the slope
// φ_b/S, φ_b from R̂ (an assembly: the residual holds φ, not R̂).
void BearingModel::parameter_derivative_given(std::span<const double> u, std::span<const double> r,
                                              std::span<double> derivative) const {
  if (derivative.size() != u.size() || r.size() != u.size())
    throw InternalError("parameter_derivative: size mismatch");
  std::fill(derivative.begin(), derivative.end(), 0.0);
  if (gear_stop()) {
    std::vector<double> residual(u.size());
    Assembler a(&pattern_, residual, {});
    AssemblyTotals t;
    assemble(u, a, &t);
    derivative[std::size_t(rigid_offset_ + 3)] = t.stop_reaction_slope / force_scale();
    return;
  }
  for (Index k = 0; k < 4; ++k) {
    const std::size_t row = std::size_t(rigid_offset_ + k);
    derivative[row] = ((k == 3 ? 1.0 : 0.0) - r[row]) / load_;
  }
}

// A component row is (heat in − heat out)·s_k with s_k = 1/(reference conductance)
// (K/W), oriented to −(gains − losses)·s_k; the node's balance ρ c t A_k dT/dt =
// gains − losses then reads C_k dT̂/dt = −F_k with C_k = ρ c t A_k s_k, in seconds.
std::vector<double> BearingModel::heat_capacities() const {
  std::vector<double> c(std::size_t(size()), 0.0);
  for (const ComponentHeat& comp : components_) {
    for (int local = 0; local < comp.node_count(); ++local) {
      const int ring = comp.axisymmetric ? local : local / comp.grid.circumferential_nodes();
      c[std::size_t(comp.offset + local)] = comp.capacity_per_area * comp.node_area(ring);
    }
  }
  return c;
}

std::vector<double> BearingModel::capacities() const {
  // In slow time (docs/physics.md section 20, [W4]) the worn depths alone, in σ_ref per
  // hour (their rows, wear_effect.cpp).
  if (time_scale_ == TimeScale::wear) {
    std::vector<double> c(std::size_t(size()), 0.0);
    for (const UnknownBlock& b : layout_.blocks())
      if (b.effect == BlockEffect::wear) std::fill(c.begin() + b.offset, c.begin() + b.offset + b.size, 1.0);
    return c;
  }
  std::vector<double> c = heat_capacities();
  for (std::size_t k = 0; k < c.size(); ++k)
    if (c[k] > 0.0) c[k] *= layout_.row_scale(Index(k));
  return c;
}

// KINSOL measures a Newton step as ‖D·δu‖₂ and caps it: weighting the rigid body fully
// and the field unknowns lightly makes the cap a limit on how far one step may move
// the washer and gear (in σ), where the exponential contact law punishes overshoot;
// temperatures (K) and pressures (p_ref) may move freely.
std::vector<double> BearingModel::step_weights() const {
  std::vector<double> d(std::size_t(size()), 1e-3);
  for (const auto& b : layout_.blocks())
    if (b.effect == BlockEffect::mechanics)
      for (Index k = b.offset; k < b.offset + b.size; ++k) d[std::size_t(k)] = 1.0;
  return d;
}

// The washer's plate answers its loads at once (docs/physics.md section 21): its mixed
// form [E1]-[E3] is a constraint, not a relaxation (relaxed in pseudo-time, the curvature
// sum's rows drive an unstable mode at the free edges).
std::vector<char> BearingModel::held_in_pseudo_time() const {
  std::vector<char> held;
  for (const UnknownBlock& b : layout_.blocks()) {
    if (b.effect != BlockEffect::elastic_washer) continue;
    held.resize(std::size_t(size()), 0);
    std::fill(held.begin() + b.offset, held.begin() + b.offset + b.size, 1);
  }
  return held;
}

}  // namespace twb
