// The duty cycle's watch on the failure criteria (cycle_watch.h).
#include "study/time/cycle_watch.h"

#include <utility>

namespace twb {

// A temperature's margin with every temperature at the ambient (its limit above it), the
// least film ratio itself (docs/physics.md section 19): the margin divided by it is 1 at
// rest and 0 on the limit, whatever the criterion's unit.
PerCriterion<std::optional<double>> CycleWatch::allowances(const OperatingLimits& limits, double ambient) {
  LimitValues rest;
  rest.thermal = true;
  rest.washer_mean_temperature = rest.oil_peak_temperature = ambient;
  rest.contact_temperature = ambient;  // nothing slides: no flash
  rest.body_temperature.fill(ambient);  // (and no contact force at no speed: no PV)
  const FailureMargins at_rest(rest, limits);
  PerCriterion<std::optional<double>> room;
  for (std::size_t c = 0; c < room.size(); ++c)
    room[c] = kFailureCriteria[c] == LimitKind::film_ratio ? limits.min_film_ratio : at_rest[c];
  return room;
}

void CycleWatch::sample(double t, const SchedulePoint& inputs, BearingState state) {
  TrajectorySample& s = out_.trajectory.emplace_back();
  s.time = t;
  s.ambient = inputs.ambient;
  s.tilt = inputs.tilt;
  s.state = std::move(state);
  const FailureMargins margins(LimitValues::of(s.state, thermal_), limits_);
  if (const std::optional<FailureMargins::Least> least = margins.least_share(allowances_))
    s.least_margin = least->share, s.least_criterion = least->kind;
  if (last_margins_) {
    const TrajectorySample& before = out_.trajectory[out_.trajectory.size() - 2];
    for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
      if (!margins.crossed_since(*last_margins_, c)) continue;
      const double a = *(*last_margins_)[c], b = *margins[c];
      std::optional<SchedulePoint> at = locate_(before.time, t, kFailureCriteria[c]);
      if (!at) {
        // Where the margin's line between the two samples is zero: within IDA's step.
        const double share = a / (a - b);
        const auto between = [&](double a0, double a1) { return a0 + share * (a1 - a0); };
        at = inputs;
        at->time = between(before.time, t);
        at->load = between(before.state.load, s.state.load);
        at->speed = between(before.state.speed, s.state.speed);
        at->ambient = between(*before.ambient, *s.ambient);
        at->tilt = between(*before.tilt, *s.tilt);
      }
      CycleEvent& e = event(b < 0.0 ? "crossing" : "recovery", at->time, *at);
      e.criterion = kFailureCriteria[c];
      e.margin = 0.0;
    }
  }
  last_margins_ = margins;
  if (s.least_margin && (!worst_ || *s.least_margin < *out_.trajectory[*worst_].least_margin))
    worst_ = out_.trajectory.size() - 1;
}

CycleEvent& CycleWatch::event(std::string what, double t, const SchedulePoint& inputs) {
  CycleEvent& e = events_.emplace_back();
  e.time = t;
  e.event = std::move(what);
  e.load = inputs.load;
  e.speed = inputs.speed;
  e.ambient = inputs.ambient;
  e.tilt = inputs.tilt;
  return e;
}

}  // namespace twb
