// The fold seen coming on a branch continued in load (the distress search's hand-over
// from natural to arclength continuation).
#pragma once

#include <cmath>
#include <utility>

namespace twb {

// Where the fold is, from the slowest relaxation rate μ of the states approaching it:
// at a saddle-node μ vanishes like √(λ* − λ), so μ² is linear in λ near the fold, and
// the line through the last two states' μ² meets zero near λ*. Farther away μ² bends
// (the estimate then lies beyond the fold), so the estimate only says when to hand
// over to arclength continuation, never where the fold is.
class FoldApproach {
 public:
  void add(double load, double rate) {
    previous_ = last_;
    last_ = {load, rate * rate};
  }
  // No estimate (inf) until μ² falls between two states, nor once disabled.
  double fold_estimate() const {
    if (disabled_ || !(previous_.first > 0.0) || !(last_.second < previous_.second)) return INFINITY;
    const double slope = (previous_.second - last_.second) / (last_.first - previous_.first);
    return last_.first + last_.second / slope;
  }
  // Within 3 % of the load: arclength continuation's first steps (0.2 % of the load,
  // growing 1.5-fold) reach the fold in a few states from there.
  bool near(double load) const { return fold_estimate() - load < 0.03 * load; }
  // Where the slowest mode slowed without a fold (near a cusp) it is no guide: no estimate
  // from here on.
  void disable() { disabled_ = true; }
  // The states added so far were not kept (the branch restarts from an earlier one).
  void forget() { previous_ = last_ = {0.0, 0.0}; }

 private:
  bool disabled_ = false;
  std::pair<double, double> previous_{0.0, 0.0}, last_{0.0, 0.0};
};

}  // namespace twb
