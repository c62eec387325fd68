// A duty cycle's summary lines (cycle_summary.h).
#include "study/time/cycle_summary.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "study/study_support.h"
#include "twb/model/operating_limits.h"
#include "twb/results/cycle_table.h"

namespace twb {

namespace {

// The hottest film temperature (K) of the trajectory's step at t.
double hottest_at(const std::vector<TrajectorySample>& trajectory, double t) {
  const auto at = std::lower_bound(trajectory.begin(), trajectory.end(), t,
                                   [](const TrajectorySample& s, double time) { return s.time < time; });
  return (at == trajectory.end() ? trajectory.back() : *at).state.max_film_temperature;
}

}  // namespace

void summarize_cycle(std::size_t segments, const OperatingSchedule& schedule,
                     std::chrono::steady_clock::time_point started, StudyOutcome& out) {
  const TrajectorySample& last = out.trajectory.back();
  const DutyCycleOutcome& cycle = std::get<DutyCycleOutcome>(out.own);
  const CycleHeat& heat = *cycle.heat;
  out.summary.push_back(fmt::format("duty cycle: {} segments, {:.6g} s to {:.6g} s, {} steps ({:.1f} s)", segments,
                                    schedule.start(), last.time,
                                    out.trajectory.size() - 1, elapsed_ms(started) / 1000.0));
  out.summary.push_back(fmt::format(
      "duty cycle: heat: {:.6g} J generated = {:.6g} J to the ambient + {:.6g} J carried by the oil + {:.6g} J stored in "
      "the bodies, to {:.2g} J ({:.2g} of the generated)",
      heat.generated, heat.to_ambient, heat.carried, heat.stored, heat.error(),
      std::abs(heat.error()) / std::max(heat.generated, 1e-300)));
  for (const CycleEvent& e : cycle.events) {
    if (e.event == "crossing" || e.event == "recovery")
      out.summary.push_back(fmt::format("duty cycle: {} {} at t = {:.6g} s ({:.6g} N, {:.6g} rad/s)",
                                        e.event == "crossing" ? "crosses" : "recovers from",
                                        criterion_phrase(*e.criterion), e.time, e.load, e.speed));
    else if (e.event == "runaway")
      out.summary.push_back(fmt::format("duty cycle: thermo-viscous runaway at t = {:.6g} s ({:.6g} N, {:.6g} rad/s)",
                                        e.time, e.load, e.speed));
    else if (e.event == "settled")
      out.summary.push_back(fmt::format("duty cycle: the runaway is over at t = {:.6g} s ({:.6g} N, {:.6g} rad/s): "
                                        "the slow thermal mode is stable again, the hottest film at {:.4g} degC",
                                        e.time, e.load, e.speed, hottest_at(out.trajectory, e.time) - 273.15));
    else if (e.event == "rest")
      out.summary.push_back(fmt::format("duty cycle: unloaded at rest from t = {:.6g} s ({:.3g} N, {:.3g} rad/s): the "
                                        "washer and gear held where they came to rest",
                                        e.time, e.load, e.speed));
    else if (e.event == "resume")
      out.summary.push_back(fmt::format("duty cycle: the washer and gear balanced again from t = {:.6g} s ({:.3g} N, "
                                        "{:.3g} rad/s)",
                                        e.time, e.load, e.speed));
    else if (e.event == "worst")
      out.summary.push_back(fmt::format(
          "duty cycle: the worst moment is t = {:.6g} s ({:.6g} N, {:.6g} rad/s): {:.3g} of {}'s allowance left{}",
          e.time, e.load, e.speed, e.margin.value_or(0.0), e.criterion ? criterion_phrase(*e.criterion) : "",
          e.failure_load ? fmt::format("; it would fail there at {:.6g} N by {}", *e.failure_load,
                                       e.failure_criterion ? criterion_name(*e.failure_criterion) : "")
                         : ""));
  }
}

}  // namespace twb
