// The fold proven by the dynamics (the distress search's proof: two transients half a
// bracket width either side of the fold located by continuation).
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "model/bearing_model.h"
#include "twb/results/trajectory_table.h"
#include "solver/runaway.h"
#include "study/searches/distress_search.h"

namespace twb {

// States of the cool branch, (load, state), in the order continuation found them.
using BranchStates = std::vector<std::pair<double, std::vector<double>>>;

// Two Newton-converged states of the same branch at the same load agree to about the
// residual tolerance times the Jacobian's conditioning (≲ 1e-7 in the scaled unknowns:
// σ, K); states of different branches differ by whole kelvins and σ. 1e-4 separates
// them with orders of magnitude on either side.
inline bool same_state(std::span<const double> a, std::span<const double> b) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::abs(a[k] - b[k]));
  return d <= 1e-4;
}

// The fold proven by the dynamics: from the highest cool state below it, a load step to
// just below the fold (half a bracket width) must settle on the cool branch, and from
// there a step to just above it must run away. Those two transients are the bracket;
// not valid, with the reason, when the dynamics disagree.
struct FoldProof {
  Bracket bracket;
  // The step above the fold as far as its verdict: its trajectory and last state, from
  // which the march to where it goes continues.
  std::vector<TrajectorySample> runaway;
  std::vector<double> runaway_state;
  double runaway_time = 0.0;
};

// cool: the cool branch's states from natural continuation; approach: those arclength
// continuation passed on its way to the fold (the step below starts from the nearest
// of either). say: progress lines. Leaves the load at the bracket's low end.
FoldProof prove_fold(BearingModel& model, const BranchStates& cool, const BranchStates& approach, double fold,
                     const RunawaySettings& runaway, bool keep_trajectory, SearchCounts& counts,
                     const SearchProgress& say);

}  // namespace twb
