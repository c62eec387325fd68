// How the fold's load moves with an input (study type sensitivity, docs/physics.md
// section 16): dW_d/dp = −ψᵀF_p / ψᵀF_W, ψ the left null vector of J at the fold.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "solver/fold_location.h"
#include "study/uncertainty/input_neighbours.h"

namespace twb {

struct SettledFold {
  double load = 0.0;        // W_d, N, to the solver's tolerance
  std::vector<double> u;    // the state there
  std::vector<double> psi;  // ψ, ψᵀb = 1
  double psi_load = 0.0;    // ψᵀF_W
  std::vector<double> null_vector;  // of J there: where Newton on the fold system starts from it
  double curvature = 0.0;           // FoldPoint::curvature: > 0 where the branch's load is largest
};

// The fold a search found, located again to the solver's tolerance (the search settles
// its load to the bracket only; off the fold ψ is no left null vector and the derivative
// is off by the distance), with ψ; none with the reason. The model's load is given back.
// `max_iterations` > 0 caps Newton's iterations (the scene's solver.max_iterations
// otherwise): a caller that can shorten its move rather than wait.
std::optional<SettledFold> settle_fold(BearingModel& model, const FoldPoint& found, std::string& why,
                                       int max_iterations = 0);

// The fold of the bearing moved along a line of inputs, predicted to first order from a
// settled one: the fold system G(u, λ; t) = [F; g] = 0 (fold_system.h) at inputs
// x(t) = x_a + t·d, differentiated in t, J_G·(u', λ') = −G_t, G_t a forward difference
// to `ahead`, the bearing at t = ε (the same borders, the fold's own unknowns; its O(ε)
// error is far below the prediction's own); `at` the bearing at t = 0. The prediction
// for t = 1: off the fold by O(|d|²) rather than O(|d|), so that Newton on the fold
// system reaches much further. None where the fold system's Jacobian is singular there.
std::optional<FoldPoint> predicted_fold(BearingModel& at, BearingModel& ahead, double epsilon, const SettledFold& fold);

// dW_d/dp for the input of `n`.
double fold_load_derivative(InputNeighbours& n, const SettledFold& fold);

}  // namespace twb
