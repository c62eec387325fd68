// Where the bearing fails at one operating speed (MODEL.md section 8): the cool branch
// is continued in load from a light load; every accepted state is checked by the
// pseudo-time transient (a load step from the previous state must settle on it); where
// the branch ends, the load steps that settle and those that run away bracket the
// distress load W_d, which bisection refines; pseudo-arclength continuation goes round
// the branch's turning point to locate the fold, which W_d must agree with.
//
// Verdicts (DistressRow::method):
//   "runaway; fold at …"  bracketed by transients, and the steady branch folds there
//   "runaway; no fold"    bracketed, but arclength continuation found no turning point
//   "no fold up to …"     the branch reaches load_end without a fold or a runaway
//                         (gradual heating): W_d stays empty, and the method names the
//                         load where the mean temperature rises fastest with load
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "twb/model/bearing_model.h"
#include "twb/results/distress_table.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"
#include "twb/solver/runaway.h"

namespace twb {

struct DistressSearchSettings {
  double load_start = 0.0, load_end = 0.0;  // N
  double bracket_width = 0.002;             // relative
  // load_sweep: the loads that must appear among the states (the requested grid);
  // empty for a distress map, which needs only the branch up to distress.
  std::vector<double> grid;
  // load_sweep: after distress, go on from the hot state the runaway reached.
  bool continue_past_distress = false;
};

struct DistressSearch {
  std::vector<SolvedState> states;        // in the order solved: the cool branch, then (sweep) the hot one
  std::size_t cool_states = 0;            // how many of them lie on the cool branch
  DistressRow row;
  std::vector<double> bracket_state;      // the steady state at the bracket's low load
  std::vector<TrajectorySample> runaway;  // the first load step past W_d, marched to the hot state
  bool failed = false;                    // the light load itself had no steady state
  std::string message;
};

// The runaway detector the search brackets W_d with: the scene's Newton tolerances, the
// bracket width, and departure from the cool branch counted as a runaway (a step that
// settles on a state the branch continued from its start does not reach).
RunawaySettings distress_detector(const Scene& scene, double bracket_width);

using SearchProgress = std::function<void(const std::string&)>;

// The model is left at its speed; its load ends wherever the search ended.
DistressSearch search_distress(BearingModel& model, const DistressSearchSettings& settings,
                               const SearchProgress& progress);

}  // namespace twb
