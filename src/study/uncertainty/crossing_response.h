// How a failure criterion's crossing load moves with an input (study type sensitivity,
// docs/physics.md section 16). The crossing is the root in load of the criterion's margin
// m (limit_thresholds.h) along the branch; it moves by dW_c/dp = −m_p / m_W, m_p and m_W
// the margin's total derivatives along the branch at fixed load and at fixed input, each
// through the state's own move (u_p = −J⁻¹F_p, u_W = −J⁻¹F_W).
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "solver/sparse_lu.h"
#include "study/uncertainty/input_neighbours.h"

namespace twb {

struct SettledCrossing {
  LimitKind kind = LimitKind::oil_temperature;
  double load = 0.0;       // N, where the margin is zero to the solver's tolerance
  std::vector<double> u;   // the state there
  std::unique_ptr<SparseLu> lu;  // J's factors there
  double margin_slope = 0.0;     // m_W, the margin's unit per N
};

// The crossing near (load, u) (a search's, to its bracket; or another model's), settled on the margin's root by
// Newton in load (each step the state solved again from the last): none, with the reason,
// where the branch is lost or J is singular there; a step towards a load that is not
// positive goes half the way to zero instead. The model's load is given back.
std::optional<SettledCrossing> settle_crossing(BearingModel& model, LimitKind kind, double load,
                                               std::vector<double> u, std::string& why);

// dW_c/dp for the input of `n`; J's back-substitution under `solve_lock` (KLU's solve
// writes into its factors' workspace).
double crossing_load_derivative(InputNeighbours& n, const SettledCrossing& crossing, std::mutex& solve_lock);

}  // namespace twb
