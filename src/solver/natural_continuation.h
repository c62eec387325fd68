// Natural-parameter continuation: the steady branch followed in λ itself (the bearing's
// load, docs/physics.md section 8), each step predicted from the last states and corrected by
// KINSOL's Newton at the new λ.
//
// The step adapts: it grows after an easy correction, halves after a failed one or
// after a correction that left the branch (the corrected state far from the
// extrapolated one compared with the change extrapolated, or a reversed direction of
// travel), and below a minimum step the continuation stops and says where. A branch
// turning back at a fold cannot be followed past it in λ: this is what reports the fold
// region; pseudo-arclength continuation (arclength_continuation.h) goes round it.
#pragma once

#include <string>
#include <vector>

#include "solver/branch_point.h"
#include "solver/kinsol_newton.h"

namespace twb {

enum class Predictor {
  constant,  // the last state (zeroth order)
  secant,    // extrapolated through the last two states; the tangent for the first step
  tangent,   // u + Δλ·u_λ with J·u_λ = −F_λ (solved by KLU at every state anyway)
};

struct NaturalSettings {
  NewtonSettings newton{.max_iterations = 10};  // the corrector; a cap keeps failures cheap
  Predictor predictor = Predictor::secant;
  // |Δλ| bounds; 0 means 1/20, 1e-6 and 1/4 of the whole interval |target − λ₀|.
  double initial_step = 0.0, min_step = 0.0, max_step = 0.0;
  double growth = 1.5;      // step factor after an easy correction
  int easy_iterations = 3;  // a correction this short is easy
  // A corrected state farther than this fraction of the predicted change from the
  // tangent's prediction u + Δλ·u_λ (whatever the predictor) is taken for a jump to
  // another branch. The tangent's own error is about ½(u''/u')·Δλ of the change, so 1/2
  // rejects only steps that outrun the branch's curvature.
  double max_prediction_error = 0.5;
  std::vector<double> unknown_weights;  // the norm of that test; empty: the step weights
};

struct NaturalReport {
  bool reached_target = false;
  double lambda = 0.0;  // the last accepted λ
  int accepted = 0, rejected = 0;
  long corrector_iterations = 0;  // over all corrections, rejected ones included
  std::string last_rejection;     // why the last rejected step was rejected
  // ‖u_λ‖ at the last accepted state over ‖u_λ‖ at the start: large near a fold.
  double sensitivity_growth = 1.0;
  std::string message;  // why it stopped short of the target
};

// From the steady state u at λ = start to `target`. u is replaced by the last accepted
// state, whose λ is the report's; the system's parameter is given back as it was.
NaturalReport continue_in_parameter(SteadySystem& system, std::vector<double>& u, double start, double target,
                                    const NaturalSettings& settings, const BranchCallback& on_state = {});

// The same over several legs of one branch (a search that stops at grid loads, judges
// the states between legs and plans the next): Newton's solver with its symbolic
// analysis, and the slope u_λ at the last state, carry over to a leg that starts where
// the last one ended, instead of a fresh analysis and factorization per leg. Between
// legs the system may change only through its parameter.
class NaturalContinuation {
 public:
  explicit NaturalContinuation(SteadySystem& system);
  NaturalReport continue_to(std::vector<double>& u, double start, double target, const NaturalSettings& settings,
                            const BranchCallback& on_state = {});

 private:
  SteadySystem& system_;
  KinsolNewton newton_;
  // Where the last leg ended: its state, λ and slope there.
  std::vector<double> end_, slope_;
  double end_lambda_ = 0.0;
};

}  // namespace twb
