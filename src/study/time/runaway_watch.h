// A duty cycle's watch for the thermo-viscous runaway along its trajectory.
#pragma once

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "model/bearing_model.h"
#include "solver/linear_stability.h"
#include "solver/sparse_lu.h"

namespace twb {

// The thermo-viscous runaway's signature at a point of the trajectory (docs/physics.md
// sections 8 and 19): the hottest film temperature rising ever faster, and the slowest
// thermal mode of the bearing's linearization there grown unstable. A ramp of the inputs
// alone can make the temperatures accelerate, but leaves the slow mode stable. A runaway
// is over where the temperatures no longer accelerate and the slow mode is stable again:
// on the hot branch, or back on the cool one where the load fell in time (a brief
// overload); from there another can begin.
class RunawayWatch {
 public:
  explicit RunawayWatch(BearingModel& model)
      : model_(model), factors_(model.pattern(), SparseLu::Ordering::by_size),
        residual_(std::size_t(model.size())), jacobian_(std::size_t(model.pattern().nnz())) {}

  enum class Change { none, runs_away, settles };
  bool running_away() const { return running_away_; }
  // The inputs' rates jump at a schedule point: the slow mode's trend before it says
  // nothing of after.
  void restart() { stable_checks_.clear(); }
  // What changes at (t, u), the model's inputs those of t.
  Change at(double t, double hottest, std::span<const double> u);

 private:
  double rate(double t, double hottest) const { return (hottest - hottest_[1]) / (t - times_[1]); }
  // None where J is singular (at a fold itself: the next point decides).
  std::optional<Stability> stability(std::span<const double> u, double hottest);
  // Whether the slow mode, stable at the last two checks, cannot have turned unstable by
  // the time the hottest film reaches `hottest`. Its growth rate is taken on the line
  // through the two checks in that temperature, trusted up to twice the rise between
  // them past the last and never more than kTrustedRise: in the fold's normal form
  // (physics §19), the other inputs fixed, the slow mode's rate is linear in the state
  // along its null vector, and so in the temperature; inputs that move as well (a speed,
  // an ambient) bend the line, which the cap bounds. Where the line rises towards zero,
  // only half way to where it reaches it: every check then halves the way left. Between,
  // a check (a Jacobian, its factors and a Krylov space of 24 solves) is skipped.
  bool cannot_have_turned(double hottest) const;
  // K: a ramp of the inputs raises the hottest film by some kelvins (the ten-minute
  // cycle's by up to ten): a check at least every kelvin of it.
  static constexpr double kTrustedRise = 1.0;

  BearingModel& model_;
  SparseLu factors_;
  std::vector<double> residual_, jacobian_;
  std::vector<double> times_, hottest_;
  bool running_away_ = false;
  // The hottest film temperature (K) and the slow mode's growth rate (1/s, negative) at
  // the last stable checks since the segment began.
  std::vector<std::pair<double, double>> stable_checks_;
};

}  // namespace twb
