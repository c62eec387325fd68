// An input's neighbours: the bearing built at p + kδ from the scene read again with the
// input changed (scene_inputs.h), and the fourth-order differences over them that a
// sensitivity study takes (docs/physics.md section 16).
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

// f'(0) ≈ Σ_k w_k f(o_k δ) / 12δ, fourth order: centred where the input may move both
// ways, one-sided at a bound of its range (a tilt, a friction coefficient, a supply
// pressure of zero).
struct Stencil {
  std::vector<double> offsets, weights;
};
inline const Stencil kCentred{{-2.0, -1.0, 1.0, 2.0}, {1.0, -8.0, 8.0, -1.0}};
inline const Stencil kForward{{0.0, 1.0, 2.0, 3.0, 4.0}, {-25.0, 48.0, -36.0, 16.0, -3.0}};
inline const Stencil kBackward{{0.0, -1.0, -2.0, -3.0, -4.0}, {25.0, -48.0, 36.0, -16.0, 3.0}};
// Second order, for a caller whose own tolerance is far above δ² (FORM's 10⁻³): half the
// bearings.
inline const Stencil kCentred2{{-1.0, 1.0}, {-6.0, 6.0}};
inline const Stencil kForward2{{0.0, 1.0, 2.0}, {-18.0, 24.0, -6.0}};
inline const Stencil kBackward2{{0.0, -1.0, -2.0}, {18.0, -24.0, 6.0}};

// Σ_k w_k v(k) / 12δ: the derivative at s = 0 of a quantity (or several) taken at each of
// the stencil's points k (s = o_k·δ).
std::vector<double> stencil_derivative(const Stencil& stencil, double step,
                                       const std::function<std::vector<double>(std::size_t)>& value_at);

// u − s·direction: a state moved along the (negative) direction of its change.
std::vector<double> moved_state(std::span<const double> u, std::span<const double> direction, double s);

// The bearing at an input's p + o_k·δ, each at the load the caller sets.
struct InputNeighbours {
  SceneInput input;
  double step = 0.0;  // δ, SI
  Stencil stencil = kCentred;
  std::vector<std::unique_ptr<BearingModel>> at;  // one per stencil point
  // The load neighbour k stands at for `load` (operating.load moves its own).
  double load_at(std::size_t k, double load) const;
  std::vector<double> derivative(const std::function<std::vector<double>(std::size_t)>& value_at) const {
    return stencil_derivative(stencil, step, value_at);
  }
};

// The neighbours of `base` (built from its scene, at its speed) in one input: centred, or
// one-sided where p − 2δ or p + 2δ leaves the input's range. Throws InputError where no
// stencil fits, std::invalid_argument where the input changes the unknowns (a discrete
// input). Curve parameters set on `base` other than its load and speed are not carried
// over: the neighbours are the scene's.
// `order` 4 (the sensitivity study's) or 2 (kCentred2 and its one-sided pair).
InputNeighbours input_neighbours(const BearingModel& base, SceneInput input, int order = 4);

// F_p at (u, load), in the model's scaled rows.
std::vector<double> residual_derivative(InputNeighbours& n, std::span<const double> u, double load);

}  // namespace twb
