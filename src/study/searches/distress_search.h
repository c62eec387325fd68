// Where the bearing fails at one operating speed (docs/physics.md section 8): the fold first,
// the dynamics as its proof. The cool branch is continued in load from a light load;
// every accepted state is judged by its linear stability (linear_stability.h, with the
// corrector's own factors), and only where that is inconclusive by the pseudo-time
// transient (a load step from the previous state must settle on it). As the slowest
// thermal mode slows towards the fold, pseudo-arclength continuation goes round the
// branch's turning point and the minimally augmented system locates the fold. Two
// transients then prove it: a load step to half a bracket width below the fold settles
// on the cool branch, one from there to half a width above runs away; they are the
// reported bracket. Bisection by transients is the fallback where no fold exists in
// range, where a transient check of the branch ran away first, or where the dynamics
// disagree with the fold.
//
// Verdicts (DistressRow::method):
//   "runaway; fold at …, proven by transients: …"  the fold, and the two steps that prove it
//   "runaway bracketed by bisection; …"            bisection by transients, and why (no fold,
//                                                  or the dynamics disagree with it)
//   "no fold up to …"     the branch reaches load_end without a fold or a runaway
//                         (gradual heating): W_d stays empty, and the method names the
//                         load where the mean temperature rises fastest with load, or
//                         why nothing can produce thermo-viscous distress (no thermal
//                         effect, an oil whose viscosity does not depend on temperature)
//   "the start at … is already past distress (W_d ≈ …)"   prefixed when the cold start at
//                         load_start lay on another branch than the one continued from a
//                         tenth of it, from where the search then ran
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "twb/results/distress_table.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"
#include "solver/fold_location.h"
#include "solver/linear_stability.h"
#include "solver/runaway.h"

namespace twb {

class SpareThreads;

struct DistressSearchSettings {
  double load_start = 0.0, load_end = 0.0;  // N
  double bracket_width = 0.002;             // relative
  // load_sweep: the loads that must appear among the states (the requested grid);
  // empty for a distress map, which needs only the branch up to distress.
  std::vector<double> grid;
  // After W_d, march the first runaway step to the hot state it reaches (its trajectory
  // and that state are results). A distress map needs neither: W_d is proven once the
  // step above the fold is judged a runaway.
  bool march_past_distress = true;
  // The fold of the branch continued from load_start only, without transients or a
  // check of the start's branch (the error estimate's refined meshes): row.fold_load.
  bool fold_only = false;
  // How each cool-branch state's stability is judged (an inconclusive verdict sends the
  // state to the transient).
  StabilitySettings stability;
  // load_sweep: after distress, go on from the hot state the runaway reached.
  bool continue_past_distress = false;
  // Keep each state's unknowns (DistressSearch::state_vectors), for an error bar on
  // every state (study.error_estimate: every_state).
  bool keep_state_vectors = false;
  // How far past the first failure criterion it crosses the cool branch is searched, as
  // a factor of that load (a distress map's study.search_past_failure); 0: on to load_end.
  double search_past_failure = 0.0;
  // The failure loads' error bars (study.error_estimate other than none): W_d's fold and
  // each criterion's crossing again on refined meshes, each until its bar is within
  // `error_tolerance` (relative; 0: one refinement, a bar of the formal order). The
  // studies whose rows report them ask for them (load_sweep, distress_map,
  // distress_curve); a sliding choice's, a sensitivity's or a duty cycle's search does not.
  bool failure_error_bars = false;
  double error_tolerance = 0.0;
  // Not a setting: the study's idle threads (study/spare_threads.h), one of which may
  // check the start's branch beside the search. The results do not depend on it.
  SpareThreads* spare_threads = nullptr;
};

// A study's failure search (its load range and bracket width) as a search's settings,
// the others at their defaults.
DistressSearchSettings range_settings(const FailureSearch& search);

// What a search cost: the work behind one W_d.
struct SearchCounts {
  long stability_tests = 0;  // linear stability tests of cool-branch states
  long transients = 0;       // load-step transients integrated (IDA)
  long ida_steps = 0;        // their internal steps
  long ida_factorizations = 0;  // KLU factorizations inside IDA (its linear solver setups)
  long klu_factorizations = 0;  // all KLU factorizations of the search: twb's own and IDA's
  void add(const SearchCounts& other) {
    stability_tests += other.stability_tests;
    transients += other.transients;
    ida_steps += other.ida_steps;
    ida_factorizations += other.ida_factorizations;
    klu_factorizations += other.klu_factorizations;
  }
  void add(const StepOutcome& step) {
    ++transients;
    ida_steps += step.statistics.steps;
    ida_factorizations += step.statistics.linear_setups;
  }
};

struct DistressSearch {
  std::vector<SolvedState> states;        // in the order solved: the cool branch, then (sweep) the hot one
  std::size_t cool_states = 0;            // how many of them lie on the cool branch
  // The load the branch was searched to: load_end, or less where search_past_failure
  // bounded it (W_d and crossings are reported up to here only).
  double searched_to = 0.0;
  DistressRow row;
  std::vector<double> bracket_state;      // the steady state at the bracket's low load
  std::optional<FoldPoint> fold;          // the located fold (state, load, null vector)
  std::vector<TrajectorySample> runaway;  // the first load step past W_d, marched to the hot state
  bool failed = false;                    // the light load itself had no steady state
  // The study's start lay past distress (not on the branch continued from a light
  // load): the search ran from a tenth of it instead, and its states begin there.
  bool start_past_distress = false;
  // W_d is a fold the branch from the start reached through stable states, proven by
  // the two transients beside it (no bisection, no runaway on the way).
  bool fold_proven = false;
  std::string message;
  SearchCounts counts;
  // The solvers' own words where a search went on regardless (e.g. why natural
  // continuation stopped at the fold): for --verbose, not for the progress lines.
  std::vector<std::string> diagnostics;
  // Each failure criterion's crossing on the branch (load, state), in kFailureCriteria
  // order, empty where it is not crossed: where a limit curve starts (not journaled).
  std::vector<std::pair<double, std::vector<double>>> crossing_states;
  // Each state's unknowns, beside `states`, where settings.keep_state_vectors asks for
  // them (not journaled).
  std::vector<std::vector<double>> state_vectors;
};

// The runaway detector the search brackets W_d with: the scene's Newton tolerances, the
// bracket width, and departure from the cool branch counted as a runaway (a step that
// settles on a state the branch continued from its start does not reach).
RunawaySettings distress_detector(const Scene& scene, double bracket_width);

using SearchProgress = std::function<void(const std::string&)>;

// The model is left as it was given: its speed, and its load (held by a ParameterScope).
DistressSearch search_distress(BearingModel& model, const DistressSearchSettings& settings,
                               const SearchProgress& progress);

}  // namespace twb
