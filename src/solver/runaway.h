// Distress as a runaway of the pseudo-time transient (physics §8), generic over
// SteadySystem: a step of the parameter λ (the load) is applied to a steady state and
// the transient C·u' = −F(u; λ) (physics §7's capacities) decides what happens.
//
//  - Settled: the trajectory reaches a steady state, proved by Newton (KINSOL) from a
//    point of the trajectory landing close to that point.
//  - Runaway: the trajectory's rate ‖C·u'‖∞ passes a minimum and grows again
//    (acceleration), or IDA cannot continue (a finite-time blow-up), or at the horizon
//    no steady state lies near the trajectory (the ghost of a saddle-node just past
//    the fold: the trajectory crawls, but nothing is there to settle on).
//
// Below the fold the rate falls monotonically toward a steady state; above it the rate
// has a minimum at the ghost and then grows without bound. Both signatures grow
// sharper, not weaker, with time, so no threshold decides the verdict: the numeric
// settings only decide when it is read (tests/solver/runaway_test.cpp halves and
// doubles each of them).
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "solver/ida_transient.h"
#include "solver/kinsol_newton.h"
#include "system/steady_system.h"

namespace twb {

struct RunawaySettings {
  TransientSettings transient;
  // The settle test's Newton. A point of a trajectory that has slowed near a stable
  // steady state is well inside Newton's quadratic basin (the semismooth cavitation
  // rows converge superlinearly there, in under ten steps): 20 iterations are generous,
  // and bound the cost of the attempts that fail near a ghost, where no root exists and
  // every iteration backtracks (on the bearing 200 iterations took 1346 residuals there).
  NewtonSettings newton{.residual_tolerance = 1e-10, .step_tolerance = 1e-14, .max_iterations = 20,
                        .max_step = 20.0};
  // Newton is tried once the rate has fallen by this factor from its start (and again
  // after each further fall by it) while falling. 10: in the linear regime the state is
  // then a tenth of the way from the steady state it left, so "close" is clear-cut, and
  // the fast initial transient (algebraic adjustment, boundary layers) has passed.
  double slowdown_factor = 10.0;
  // Runaway when the rate exceeds this multiple of its running minimum (a minimum under
  // Newton's residual tolerance counts as that tolerance: rounding noise). A settling
  // step's rate falls, apart from the non-monotonicity coupled modes can show; past a
  // fold it regrows without bound (blow-up) or 40-300-fold on the way to a hot branch
  // (the S-curve test), so a large factor costs little time and buys certainty.
  double acceleration_factor = 10.0;
  // The horizon, in slowest relaxation times at the start state (relaxation_time.h): 50
  // allows a settle from any point of the step's basin to the slowdown factor (e^−50
  // decay in the linear regime) even where the approach to a state near the fold is
  // ten times slower than at the start; a ghost's bottleneck outlasting it is
  // decided by the Newton test, which has no root to find there.
  double horizon_multiple = 50.0;
  // A Newton result u* counts as near the trajectory point u(t) if its distance (in
  // the differential unknowns, in units of the integration tolerance) is at most this
  // multiple of the distance u(t) has travelled from the start (or of the tolerance
  // itself, for a step that barely moves). 1: in the linear regime at the slowdown
  // factor the ratio is 1/9; a far branch (the hot one past distress) is many times the
  // step's travel away.
  double closeness = 1.0;
  // Inverse iterations for the slowest relaxation time: only its order of magnitude
  // matters (the horizon multiple absorbs the rest); 20 iterations shrink the other
  // modes' share by (τ_2/τ_1)^20, and nearly degenerate slow modes give the right
  // scale anyway.
  int relaxation_iterations = 20;
  // bracket_critical stops when (high − low)/|high| is at most this. 0.2 %: the
  // midpoint is then within 0.1 % of the fold, five times inside physics §8's 0.5 %
  // robustness requirement, for about log2(range/0.002) trials.
  double relative_width = 0.002;
  // Departure from the continued branch is a runaway too (physics §8): a step that
  // settles, but on a steady state the branch through the start does not reach (the
  // hot branch past a fold, landed on without an acceleration the factor would see),
  // has left it. When set, a settled verdict must pass this test: given the start (a
  // steady state at start_parameter) and the settled state at parameter, does the
  // branch continued from the one reach the other? The system may be left at any λ.
  // Empty: any steady state counts as settled.
  std::function<bool(SteadySystem& system, std::span<const double> start, double start_parameter,
                     std::span<const double> settled, double parameter)>
      on_branch;
};

enum class StepVerdict { settled, runaway };

// What decided the verdict.
enum class StepEvidence {
  steady_state_found,     // settled: Newton from the trajectory landed near it
  acceleration,           // runaway: the rate grew from its minimum by the factor
  integration_failure,    // runaway: IDA could not continue (a blow-up)
  no_steady_state_nearby, // runaway: at the horizon Newton found no steady state near u(t)
  // Runaway by default, but the dynamics were never read: IDACalcIC found no
  // consistent algebraic state at the new parameter (on the bearing: no film that
  // carries the new load at the old temperatures, or a numerical failure).
  no_consistent_start,
  left_branch  // runaway: settled, but off the branch continued from the start (on_branch)
};

struct RateSample {
  double time;
  double rate;  // ‖C·u'‖∞ = max |F_k(u(t); λ)| over the differential rows
};

struct StepOutcome {
  StepVerdict verdict = StepVerdict::runaway;
  StepEvidence evidence = StepEvidence::integration_failure;
  // Settled: the steady state Newton found. Runaway: the last state integrated.
  std::vector<double> final_state;
  double time = 0.0;             // transient time reached when the verdict was read
  double horizon = 0.0;
  double relaxation_time = 0.0;  // slowest, at the start state
  std::vector<RateSample> samples;  // one per internal IDA step, and t = 0
  int newton_attempts = 0;
  TransientStatistics statistics;
  std::string reason;
  bool settled() const { return verdict == StepVerdict::settled; }
};

// Steps the system from start_state, a steady state at λ = start_parameter, to
// λ = new_parameter, and integrates the transient until the verdict (whose states are at
// new_parameter). The observer, if given, sees every internal step. The system's
// parameter is given back as it was.
StepOutcome classify_step(SteadySystem& system, std::span<const double> start_state, double start_parameter,
                          double new_parameter, const RunawaySettings& settings,
                          const TransientObserver& observer = {});

struct BracketStep {
  double parameter;
  StepVerdict verdict;
  StepEvidence evidence;
  double time;
  std::string reason;
};

struct Bracket {
  bool valid = false;  // low settled (its state is steady) and high ran away from it
  double low = 0.0, high = 0.0;
  std::vector<double> low_state;  // the steady state at low
  std::vector<BracketStep> steps;
  std::string message;  // why the bracket is not valid
  long ida_steps = 0;   // over all its transients
  long ida_factorizations = 0;
  double critical_estimate() const { return 0.5 * (low + high); }
};

// Called after each trial of a bisection (progress lines).
using BracketObserver = std::function<void(const BracketStep&)>;

// Bisection on λ between a settled and a runaway step until
// (high − low)/|high| ≤ settings.relative_width. Every trial starts from the steady
// state at the current low, as a load step does on a running machine. low_state is
// polished by Newton at low_parameter first. While no runaway is proven, a step too
// large to start (no consistent state: StepEvidence::no_consistent_start) is retried
// halfway and a settled one raises low, so the search walks up toward
// high_parameter; once a runaway is proven, a trial that cannot start ends the search
// (not valid): a bracket must rest on dynamics that were integrated. The system's
// parameter is given back as it was.
Bracket bracket_critical(SteadySystem& system, double low_parameter, std::span<const double> low_state,
                         double high_parameter, const RunawaySettings& settings, const BracketObserver& observer = {});

}  // namespace twb
