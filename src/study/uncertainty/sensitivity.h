// What a run reports, differentiated with respect to the scene's inputs (study type
// sensitivity, docs/physics.md section 16).
//
// A state u of F(u; p) = 0 moves with an input p by u_p = −J⁻¹F_p (the implicit function
// theorem: one back-substitution with J's factors per input), and a reported quantity
// q(u; p) by dq/dp = q_u·u_p + q_p, the derivative of Q(s) = q(u + s·u_p; p + s) at s = 0.
// The fold's load moves by dW_d/dp = −ψᵀF_p / ψᵀF_W, ψ the left null vector of J at the
// fold. F_p and Q' are fourth-order centred differences over p ± δ, p ± 2δ, of the
// bearing built from the scene read again with the input changed (scene_inputs.h), so
// that everything derived from an input follows it (a data sheet's viscosity fit, the
// summits of a roughness, the pressure scale of a load); δ = 1e-4·|p| (of a unit's
// typical size where p = 0). Fourth order, because F at fixed unknowns bends steeply in
// some inputs (a gear's tilt moves the rim's gap by a few hundredths of σ per 10⁻³ of
// itself): the second-order difference was 3·10⁻⁵ off W_d's derivative there.
#pragma once

#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "solver/sparse_lu.h"
#include "study/uncertainty/input_neighbours.h"
#include "twb/study/study_outcome.h"

namespace twb {

// The quantities a sensitivity study differentiates, of a state: name (the column's), value.
struct StateQuantity {
  const char* name;
  double value;
  bool temperature;  // written in °C; its elasticity is relative to its rise above the ambient
};
std::vector<StateQuantity> state_quantities(const BearingState& s);

// The factors of J at state u of `model` (at its load), for u_p = −J⁻¹F_p; null where J
// is singular (a fold: the state does not move smoothly with the inputs).
std::unique_ptr<SparseLu> jacobian_factors(const BearingModel& model, std::span<const double> u);

// dq/dp of each of state_quantities at state u of the neighbours' base (at `load`), J's
// factors there in `lu`, its back-substitution under `solve_lock`.
std::vector<double> state_derivatives(InputNeighbours& n, std::span<const double> u, double load, const SparseLu& lu,
                                      std::mutex& solve_lock);

// The study: the state at the scene's operating point (and with a load range, its fold)
// and every quantity's derivative against every input, on `threads` threads (the same
// numbers for any count).
void run_sensitivity(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads);

}  // namespace twb
