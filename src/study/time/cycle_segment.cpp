// The duty cycle's steps 1 and 2 (duty_cycle_march.h): each segment of the schedule
// marched, and an unloaded washer's rest.
#include "study/time/duty_cycle_march.h"

#include <fmt/format.h>

namespace twb {

namespace {

// The washer unloaded at rest (load and speed both zero) is held where it came to rest
// (BearingModel::hold_at_rest, physics §19), from a millionth of the segment before the
// point where it comes to rest to a millionth of the segment after it leaves: the
// massless bodies' positions have a limit as the load and the speed go to zero, none at
// the zero itself (the free gear climbs up film 2's asperity tail without end). Where
// the march cannot follow them that close to the zero (IDA's Newton fails on the film
// of a load and a speed a millionth of their ramps), the rest begins where it stopped
// and ends where the balances find a consistent state, within a thousandth.
constexpr double kRestMargin = 1e-6, kRestReach = 1e-3;

std::string no_start(double t, const TransientStatus& status) {
  return fmt::format("no consistent state at t = {:.6g} s: {}", t, status.message);
}

}  // namespace

void DutyCycleMarch::follow_schedule() {
  for (; segment_ < schedule_.segments() && ended_.empty(); ++segment_) march_segment();
  bank();
  model_.hold_at_rest({});
  model_.set_imposed_tilt_rate(0.0);  // quasi-steady from here on (the worst moment's search)
  march_form_.reset();
}

void DutyCycleMarch::march_segment() {
  const SchedulePoint& a = schedule_.points()[segment_];
  const SchedulePoint& b = schedule_.points()[segment_ + 1];
  if (progress_)
    progress_(fmt::format("duty cycle: segment {} of {}, {:.6g} s to {:.6g} s", segment_ + 1, schedule_.segments(),
                          a.time, b.time));
  const double span = b.time - a.time;
  const bool rest_a = OperatingSchedule::unloaded_at_rest(a), rest_b = OperatingSchedule::unloaded_at_rest(b);
  if (rest_a) {
    rest_at_start(a, b, span, rest_b);
    if (!ended_.empty() || rest_b) return;
  } else if (const TransientStatus status = start_at(a.time); !status.ok) {
    ended_ = no_start(a.time, status);
    return;
  }
  const std::string stopped = step_to(rest_b ? b.time - kRestMargin * span : b.time);
  // Coming to rest, within the last thousandth of the segment: the rest begins there.
  if (!stopped.empty() && !(rest_b && ida_.time() >= b.time - kRestReach * span)) {
    ended_ = stopped;
    return;
  }
  if (!rest_b) return;
  const double from = ida_.time();
  model_.hold_at_rest(u_);
  rest_event(true, from);
  if (const TransientStatus held = start_at(from); !held.ok) {
    ended_ = no_start(from, held);
    return;
  }
  if (const std::string held_short = step_to(b.time); !held_short.empty()) ended_ = held_short;
}

// Held a millionth of the segment, then balanced again; where the balances find no
// consistent state that close to the zero, held a decade longer, up to a thousandth.
// (Held since the segment before came to rest: a schedule does not start at rest.)
void DutyCycleMarch::rest_at_start(const SchedulePoint& a, const SchedulePoint& b, double span, bool rest_b) {
  double from = a.time;
  if (!model_.held_at_rest()) {
    model_.hold_at_rest(u_);
    rest_event(true, from);
  }
  std::string why;
  for (double reach = kRestMargin; why.empty(); reach *= 10.0) {
    const TransientStatus held = start_at(from);
    if (!held.ok) {
      ended_ = no_start(from, held);
      break;
    }
    const double until = rest_b ? b.time : a.time + reach * span;
    if (const std::string stopped = step_to(until); !stopped.empty()) {
      ended_ = stopped;
      break;
    }
    from = until;
    if (rest_b) break;
    model_.hold_at_rest({});
    const TransientStatus balanced = start_at(from);
    if (balanced.ok) {
      rest_event(false, from);
      break;
    }
    model_.hold_at_rest(u_);  // the rigid unknowns held are the rest's still
    if (reach * 10.0 > kRestReach * (1.0 + 1e-9)) {
      why = no_start(from, balanced);
      // Unloaded, a free gear leaves nothing to press the turning washer down (physics §19).
      if (b.load == 0.0)
        why += "; the washer left its rest with the speed alone, unloaded: bring the load back first, or with the "
               "speed";
    }
  }
  if (!why.empty()) ended_ = why;
}

void DutyCycleMarch::rest_event(bool held, double t) {
  watch_.event(held ? "rest" : "resume", t, schedule_.on_segment(segment_, t));
  if (progress_)
    progress_(fmt::format("duty cycle: {} at t = {:.6g} s",
                          held ? "unloaded at rest, the washer and gear held" : "the washer and gear balanced again",
                          t));
}

}  // namespace twb
