// The duty cycle's watch on the failure criteria (cycle_watch.h).
#include "study/cycle_watch.h"

#include <utility>

namespace twb {

namespace {

// How far a criterion lets the state move from rest: a temperature's margin with every
// temperature at the ambient (its limit above it), the least film ratio itself (docs/
// physics.md section 19); the margin divided by it is 1 at rest and 0 on the limit,
// whatever the criterion's unit.
std::optional<double> allowance(LimitKind kind, const OperatingLimits& limits, double ambient) {
  if (kind == LimitKind::film_ratio) return limits.min_film_ratio;
  LimitValues rest;
  rest.thermal = true;
  rest.washer_mean_temperature = rest.oil_peak_temperature = ambient;
  rest.contact_temperature = ambient;  // nothing slides: no flash
  rest.body_temperature.fill(ambient);  // (and no contact force at no speed: no PV)
  return failure_margin(kind, rest, limits);
}

}  // namespace

void CycleWatch::sample(double t, const SchedulePoint& inputs, BearingState state) {
  TrajectorySample& s = out_.trajectory.emplace_back();
  s.time = t;
  s.ambient = inputs.ambient;
  s.tilt = inputs.tilt;
  s.state = std::move(state);
  const LimitValues values = LimitValues::of(s.state, thermal_);
  Margins margins;
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    const LimitKind kind = kFailureCriteria[c];
    margins[c] = failure_margin(kind, values, limits_);
    const std::optional<double> room = allowance(kind, limits_, lowest_ambient_);
    if (!margins[c] || !room || !(*room > 0.0)) continue;
    const double fraction = *margins[c] / *room;
    if (!s.least_margin || fraction < *s.least_margin) s.least_margin = fraction, s.least_criterion = kind;
  }
  if (last_margins_) {
    const TrajectorySample& before = out_.trajectory[out_.trajectory.size() - 2];
    for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
      const std::optional<double> a = (*last_margins_)[c], b = margins[c];
      if (!a || !b || (*a >= 0.0) == (*b >= 0.0)) continue;
      std::optional<SchedulePoint> at = locate_(before.time, t, kFailureCriteria[c]);
      if (!at) {
        // Where the margin's line between the two samples is zero: within IDA's step.
        const double share = *a / (*a - *b);
        const auto between = [&](double a0, double a1) { return a0 + share * (a1 - a0); };
        at = inputs;
        at->time = between(before.time, t);
        at->load = between(before.state.load, s.state.load);
        at->speed = between(before.state.speed, s.state.speed);
        at->ambient = between(*before.ambient, *s.ambient);
        at->tilt = between(*before.tilt, *s.tilt);
      }
      CycleEvent& e = event(*b < 0.0 ? "crossing" : "recovery", at->time, *at);
      e.criterion = kFailureCriteria[c];
      e.margin = 0.0;
    }
  }
  last_margins_ = margins;
  if (s.least_margin && (!worst_ || *s.least_margin < *out_.trajectory[*worst_].least_margin))
    worst_ = out_.trajectory.size() - 1;
}

CycleEvent& CycleWatch::event(std::string what, double t, const SchedulePoint& inputs) {
  CycleEvent& e = out_.cycle_events.emplace_back();
  e.time = t;
  e.event = std::move(what);
  e.load = inputs.load;
  e.speed = inputs.speed;
  e.ambient = inputs.ambient;
  e.tilt = inputs.tilt;
  return e;
}

}  // namespace twb
