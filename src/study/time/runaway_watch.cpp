// The duty cycle's runaway watch (runaway_watch.h).
#include "study/time/runaway_watch.h"

#include <algorithm>

#include "system/steady_system.h"

namespace twb {

RunawayWatch::Change RunawayWatch::at(double t, double hottest, std::span<const double> u) {
  const bool known = times_.size() == 2;
  const double now = known ? rate(t, hottest) : 0.0;
  const bool accelerating = known && now > 0.0 && now > (hottest_[1] - hottest_[0]) / (times_[1] - times_[0]);
  if (times_.size() == 2) times_.erase(times_.begin()), hottest_.erase(hottest_.begin());
  times_.push_back(t);
  hottest_.push_back(hottest);
  // A film cooler than at the last check has come back by another way: its line is spent.
  if (!stable_checks_.empty() && hottest < stable_checks_.back().first) stable_checks_.clear();
  if (!known || accelerating == running_away_) return Change::none;
  if (!running_away_ && cannot_have_turned(hottest)) return Change::none;
  const std::optional<Stability> slow_mode = stability(u, hottest);
  if (!running_away_ && slow_mode == Stability::unstable) {
    running_away_ = true;
    return Change::runs_away;
  }
  if (running_away_ && slow_mode == Stability::stable) {
    running_away_ = false;
    return Change::settles;
  }
  return Change::none;
}

std::optional<Stability> RunawayWatch::stability(std::span<const double> u, double hottest) {
  const NewtonForm own_rows(model_, false);  // the linearization of the model's own rows
  model_.evaluate(u, residual_, jacobian_);
  if (!factors_.factor(jacobian_)) {
    stable_checks_.clear();
    return std::nullopt;
  }
  const StabilityReport report = linear_stability(model_, factors_);
  if (report.verdict == Stability::stable && !report.modes.empty()) {
    if (stable_checks_.size() == 2) stable_checks_.erase(stable_checks_.begin());
    stable_checks_.push_back({hottest, report.growth_rate()});
  } else {
    stable_checks_.clear();
  }
  return report.verdict;
}

bool RunawayWatch::cannot_have_turned(double hottest) const {
  if (stable_checks_.size() < 2) return false;
  const auto [hot1, g1] = stable_checks_[0];
  const auto [hot2, g2] = stable_checks_[1];
  if (!(hot2 > hot1)) return false;
  double reach = std::min(2.0 * (hot2 - hot1), kTrustedRise);
  if (g2 > g1) reach = std::min(reach, 0.5 * -g2 * (hot2 - hot1) / (g2 - g1));
  return hottest < hot2 + reach;
}

}  // namespace twb
