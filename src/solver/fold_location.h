// Where exactly a branch turns (docs/physics.md section 8: distress is that fold, the largest
// load of the low-temperature branch), given two consecutive continuation points on
// either side of it (the λ component of the unit tangent changes sign between them).
//
// First choice: Newton (KINSOL + KLU) on the minimally augmented system [F; g] = 0
// (fold_system.h), started from the point where the sign change interpolates to zero;
// it converges quadratically to the fold, with F and the test function g both within the
// corrector's residual tolerance. Fallback, when that Newton fails or lands outside the
// bracket: the zero of t_λ(s) along the arclength between the two points, by
// Boost.Math's TOMS 748 bracketing root finder, each evaluation one pseudo-arclength
// correction and one tangent.
#pragma once

#include <limits>
#include <span>
#include <string>
#include <vector>

#include "solver/continuation_metric.h"
#include "solver/kinsol_newton.h"

namespace twb {

enum class FoldMethod {
  minimally_augmented,  // Newton on [F; g]
  arclength_bracket,    // t_λ = 0 bracketed along the arclength
  interpolated,         // both failed: linear interpolation of t_λ, an estimate only
};
const char* to_string(FoldMethod method);

struct FoldPoint {
  std::vector<double> u;
  double lambda = 0.0;
  std::vector<double> null_vector;  // spans the null space of ∂F/∂u; unit in the metric's state norm
  FoldMethod method = FoldMethod::interpolated;
  double residual_norm = 0.0;  // max-norm of [F; g] (minimally augmented) or of F (bracket)
  // κ of FoldSystem::fold_curvature where it was computed (locate_fold_near): > 0 where the
  // branch's parameter is largest, < 0 where smallest; NaN elsewhere.
  double curvature = std::numeric_limits<double>::quiet_NaN();
  long iterations = 0;         // Newton iterations, or root-finder evaluations
  std::string message;         // why a method was given up, if one was
};

// Two consecutive states of a branch in the continuation unknowns x = (u, λ/λ_scale)
// with their unit tangents; b is the correction of x_a + step·t_a onto the hyperplane
// ⟨t_a, x − x_a⟩ = step (arclength_system.h), and t_a, t_b have last components of
// opposite signs.
struct FoldBracket {
  std::vector<double> x_a, t_a, x_b, t_b;
  double step = 0.0;
};

struct FoldSettings {
  bool minimally_augmented = true;  // false: bracket directly (to test the fallback)
  int max_bracket_evaluations = 60;
};

// newton.residual_tolerance is the system's: the fold is converged when F and g are both
// within it. The system's parameter is given back as it was.
FoldPoint locate_fold(SteadySystem& system, const ContinuationMetric& metric, const FoldBracket& bracket,
                      const NewtonSettings& newton, const FoldSettings& settings = {});

// The fold near a guess of it (u at λ, and null_guess, any scale, for its null vector),
// by Newton on the minimally augmented system alone: no branch is followed, so the
// guess must be within Newton's reach, e.g. the fold of a mesh coarser by two,
// interpolated (5 % off in load on the paper's bearing). Converged: u non-empty, method
// minimally_augmented, curvature set (the caller decides whether the fold is of the
// kind it wanted). Otherwise u empty and message says why. The system's parameter is
// given back as it was. With load_accuracy > 0 (in λ's units)
// Newton stops once λ is settled to about that (NewtonSettings::watched), before F and
// g meet the residual tolerance: for a caller that needs the fold's load alone.
FoldPoint locate_fold_near(SteadySystem& system, std::span<const double> u, double lambda,
                           std::span<const double> null_guess, NewtonSettings newton, double load_accuracy = 0.0);

}  // namespace twb
