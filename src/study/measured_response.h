// What the bearing predicts for a rig's measurements (study type calibration,
// docs/physics.md section 18): at given values of the fitted inputs, each measured
// point's steady state (its load and speed set on the bearing built with those inputs)
// and the measured quantities there; with the derivatives of each quantity in each input
// where asked, by the implicit function theorem (state_derivatives, sensitivity.h: one
// back-substitution with J's factors per input, F_p by second-order differences of the
// bearing built at p ± δ).
//
// A rig loads its washer up at each speed: the points of one speed are solved in the
// order of their loads, each from the state at the load before (the lightest from its
// own last state, the cold start the first time), so that every point lies on the
// branch continued from the light load, and each prediction is a function of the inputs
// alone (never of where an earlier trial left a point: between the fold and the hot
// branch's recovery the bearing has two states). The speeds are spread over threads.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "twb/scene/scene.h"
#include "twb/study/study_outcome.h"

namespace twb {

// A measured point's predicted quantities (SI, MeasuredQuantity's order) and, where
// asked, d quantity / d input (by fitted input).
struct PointPrediction {
  std::array<double, kMeasuredQuantities> values{};
  std::array<std::vector<double>, kMeasuredQuantities> derivatives;
  SolvedState state;  // as states.csv records it
};

class MeasuredResponse {
 public:
  // scene: the bearing as a point study (its inputs as written); points: the rig's.
  MeasuredResponse(Scene scene, std::vector<FittedInput> fitted, std::vector<MeasuredPoint> points, int threads);

  // Every point at the fitted inputs' values p (SI); false, with the first failing
  // point's reason in `why`, where a point has no steady state.
  bool predict(std::span<const double> p, bool with_derivatives, std::vector<PointPrediction>& out, std::string& why);

  const std::vector<MeasuredPoint>& points() const { return points_; }
  long solves() const { return solves_; }

 private:
  Scene scene_;
  std::vector<FittedInput> fitted_;
  std::vector<MeasuredPoint> points_;
  int threads_;
  std::vector<std::vector<std::size_t>> speeds_;  // the points of each speed, by load
  std::vector<std::vector<double>> lightest_;     // each speed's lightest point's last state
  long solves_ = 0;
};

}  // namespace twb
