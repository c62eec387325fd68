// Pseudo-arclength continuation (Keller) of the steady branch F(u; λ) = 0, through
// turning points, with fold detection and location (docs/physics.md section 8: distress is the
// fold of the steady branch continued in load).
//
// Each step predicts x + Δs·t along the unit tangent (continuation_metric.h for the
// norm), corrects on the hyperplane normal to t with KINSOL + KLU (arclength_system.h),
// then takes the tangent at the new state. The step grows after an easy correction and
// halves after a failed one, or after one that turned the tangent by more than a set
// angle or moved the state far off the prediction (both signs of a jump to another
// branch or of a step too long for the branch's curvature). A sign change of the
// tangent's λ component between two states is a fold; it is located by
// fold_location.h, the continuation then goes on along the branch.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "solver/branch_point.h"
#include "solver/fold_location.h"
#include "solver/kinsol_newton.h"

namespace twb {

struct ArclengthSettings {
  NewtonSettings newton{.max_iterations = 10};  // the corrector (and the fold's Newton)
  double parameter_scale = 0.0;                 // λ_scale; 0: |λ₀| (continuation_metric.h)
  std::vector<double> unknown_weights;          // the metric's w; empty: the step weights
  // Arclength steps, in the metric: about a fraction of the state's or λ's size.
  double initial_step = 0.05, min_step = 1e-8, max_step = 0.5;
  double growth = 1.5;      // step factor after an easy correction
  int easy_iterations = 3;  // a correction this short is easy
  // Largest angle between consecutive unit tangents, and largest distance of the
  // corrected state from the prediction as a fraction of Δs. A step that resolves the
  // branch turns the tangent by κΔs and corrects by about ½κΔs², so both stay small
  // unless the step outruns the curvature κ or the corrector jumped.
  double max_turn = 0.5;  // radians
  double max_correction = 0.5;
  int max_points = 1000;  // accepted states, the start excluded
  // The continuation stops after the first state outside [lambda_min, lambda_max].
  double lambda_min = -std::numeric_limits<double>::infinity();
  double lambda_max = std::numeric_limits<double>::infinity();
  int direction = +1;  // the start tangent points to increasing (+1) or decreasing (−1) λ
  bool locate_folds = true;
  FoldSettings fold;
};

struct ArclengthReport {
  enum class Stop { parameter_bound, max_points, caller, min_step, bad_start };
  Stop stop = Stop::bad_start;
  std::string message;
  int accepted = 0, rejected = 0;
  long corrector_iterations = 0;  // over all corrections, rejected ones included
  std::string last_rejection;     // why the last rejected step was rejected
  double arclength = 0.0;         // of the last accepted state
  std::vector<double> u;          // the last accepted state
  double lambda = 0.0;
  std::vector<FoldPoint> folds;   // in the order the branch passed them
};

// From the steady state u0 at λ = lambda0. The system's parameter is given back as it was.
ArclengthReport continue_by_arclength(SteadySystem& system, std::span<const double> u0, double lambda0,
                                      const ArclengthSettings& settings, const BranchCallback& on_point = {});

}  // namespace twb
