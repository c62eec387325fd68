// An input's neighbours: the bearing built at p ± δ and p ± 2δ from the scene read again
// with the input changed (scene_inputs.h), and the fourth-order centred differences over
// them that a sensitivity study takes (docs/physics.md section 16).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "model/bearing_model.h"

namespace twb {

// The relative difference step: the fourth-order difference's truncation (δ⁴ times the
// residual's bend, up to 10⁴ of it: 10⁻¹² in all) and its rounding (10⁻¹⁶/δ on rows of
// order one that vanish at the state) both far below the solver's tolerance.
inline constexpr double kInputStep = 1e-4;

// The operating point's inputs: a built model's load and speed are set on it (a Bearing
// solves at points of its own), so their neighbours stand at the base model's ± kδ.
inline constexpr const char* kLoadInput = "operating.load";
inline constexpr const char* kSpeedInput = "operating.speed";

// The bearing at an input's p + kδ, k = −2, −1, 1, 2, each at the load the caller sets.
struct InputNeighbours {
  SceneInput input;
  double step = 0.0;  // δ, SI
  static constexpr double kOffsets[4] = {-2.0, -1.0, 1.0, 2.0};
  static constexpr double kWeights[4] = {1.0, -8.0, 8.0, -1.0};  // f' ≈ Σ w_k f(p + kδ) / 12δ
  std::unique_ptr<BearingModel> at[4];
  // The load neighbour k stands at for `load` (operating.load moves its own).
  double load_at(std::size_t k, double load) const;
};

// The neighbours of `base` (built from its scene, at its speed) in one input. Throws
// InputError where p ± 2δ leaves the input's range, std::invalid_argument where it
// changes the unknowns (a discrete input). Curve parameters set on `base` other than its
// load and speed are not carried over: the neighbours are the scene's.
InputNeighbours input_neighbours(const BearingModel& base, SceneInput input);

// F_p at (u, load), in the model's scaled rows.
std::vector<double> residual_derivative(InputNeighbours& n, std::span<const double> u, double load);

// Σ_k w_k v(k) / 12δ: the derivative at s = 0 of a quantity (or several) taken at each
// neighbour k, to fourth order in δ.
std::vector<double> neighbour_derivative(double step, const std::function<std::vector<double>(std::size_t)>& value_at);

}  // namespace twb
