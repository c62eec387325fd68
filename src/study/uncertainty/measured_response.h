// What the bearing predicts for a rig's measurements (study type calibration,
// docs/physics.md section 18): at given values of the fitted inputs, each measured
// point's steady state (its load and speed set on the bearing built with those inputs)
// and the measured quantities there; with the derivatives of each quantity in each input
// where asked, by the implicit function theorem (state_derivatives, sensitivity.h: one
// back-substitution with J's factors per input, F_p by second-order differences of the
// bearing built at p ± δ).
//
// A rig loads its washer up at each speed (and oil temperature, where the data give one
// a point): the points of one speed are solved in the
// order of their loads, the lightest from its state at the first inputs asked for (the
// cold start then), each heavier one by continuation in load from the one before, so
// that every point lies on the branch continued from the light load and each prediction
// is a function of the inputs alone (never of where an earlier trial left a point:
// between the fold and the hot branch's recovery the bearing has two states). A point
// past the fold of that branch has no prediction. The speeds are spread over threads.
// The derivatives asked for at the inputs of the last prediction reuse its states.
#pragma once

#include <array>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "solver/natural_continuation.h"
#include "study/uncertainty/input_neighbours.h"
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
  // Point k of speed g (its state u, from state_before, the point's before it, where k > 0)
  // and its record; false, with the reason in `failed`, where it has no state on the branch.
  bool solve_point(BearingModel& model, std::size_t g, std::size_t k, std::span<const double> state_before,
                   std::vector<double>& u, const NaturalSettings& settings, PointPrediction& pred, std::string& failed,
                   long& solves);
  // The point's quantities' derivatives in each fitted input at its state u (at its
  // oil temperature `ambient`).
  bool differentiate(BearingModel& model, std::vector<InputNeighbours>& neighbours, std::mutex& solve_lock,
                     const MeasuredPoint& m, double ambient, std::span<const double> u, PointPrediction& pred,
                     std::string& failed) const;

  Scene scene_;
  std::vector<FittedInput> fitted_;
  std::vector<MeasuredPoint> points_;
  int threads_;
  std::vector<std::vector<std::size_t>> speeds_;  // the points of each speed, by load
  std::vector<std::vector<double>> lightest_;     // each speed's lightest point's first state
  bool own_ambient_ = false;                      // some point has its own oil temperature
  // The last prediction that succeeded: its inputs, each point's state and record.
  std::vector<double> last_p_;
  std::vector<std::vector<double>> states_;
  std::vector<PointPrediction> last_;
  long solves_ = 0;
};

}  // namespace twb
