// The duty cycle's steps 4 and 5 (duty_cycle_march.h): the march's end, and the
// cycle's worst moment with the failure load there.
#include "study/time/duty_cycle_march.h"

#include <algorithm>
#include <exception>
#include <utility>

#include <fmt/format.h>

#include "study/searches/distress_search.h"
#include "study/study_support.h"
#include "twb/error_family.h"

namespace twb {

namespace {

// W_fail at the worst moment's speed, ambient and tilt: how close the operating point
// came to the quasi-steady failure load.
void failure_at_worst(BearingModel& model, StudyOutcome& out, const TrajectorySample& worst, double largest_load,
                      CycleEvent& e) {
  SchedulePoint p;
  p.load = worst.state.load;
  p.speed = worst.state.speed;
  p.ambient = *worst.ambient;
  p.tilt = *worst.tilt;
  OperatingSchedule::apply(model, p);
  DistressSearchSettings settings;
  // From a quarter of the load there, or of the cycle's largest where the washer was
  // unloaded (the search climbs from a load the films carry).
  settings.load_start = 0.25 * (p.load > 0.0 ? p.load : largest_load);
  settings.load_end = 10.0 * largest_load;
  settings.march_past_distress = false;
  try {
    DistressSearch found = search_distress(model, settings, {});
    add_search_work(out.timings, found.counts);
    if (found.row.failure_load) {
      e.failure_load = found.row.failure_load;
      e.failure_criterion = found.row.criterion;
    }
    out.distress.push_back(std::move(found.row));
  } catch (const InternalError&) {
    throw;
  } catch (const std::exception& ex) {
    out.summary.push_back(fmt::format("duty cycle: no failure load at the worst moment: {}", ex.what()));
  }
}

}  // namespace

bool DutyCycleMarch::check_started() {
  if (!out_.trajectory.empty()) return true;
  out_.solver_failed = true;
  out_.message = "duty cycle: the march did not start: " + ended_;
  return false;
}

void DutyCycleMarch::record_end(const std::string& bearing) {
  const TrajectorySample& last = out_.trajectory.back();
  watch_.event("end", last.time, schedule_.at(last.time)).margin = last.least_margin;
  if (ended_.empty()) {
    const SchedulePoint at = schedule_.at(last.time);
    cycle_.end = CycleState{last.time, at.load, at.speed, at.ambient, at.tilt, u_, bearing};
  }
  heat_.stored = heat_content(model_, u_, schedule_.at(last.time).ambient) - content_at_start_;
  cycle_.heat = heat_;
  if (!ended_.empty()) {
    // A blow-up (IDA stopped by temperatures running away) is the runaway itself; any
    // other end is the solver's failure.
    if (runaway_.running_away()) {
      out_.message = fmt::format("duty cycle: the trajectory blew up after the runaway: {}", ended_);
    } else {
      out_.solver_failed = true;
      out_.message = "duty cycle: the march ended early: " + ended_;
    }
  }
}

void DutyCycleMarch::worst_moment() {
  double largest_load = 0.0;
  for (const SchedulePoint& p : schedule_.points()) largest_load = std::max(largest_load, p.load);
  const std::optional<std::size_t> w = watch_.worst();
  if (!w) return;
  const TrajectorySample worst = out_.trajectory[*w];
  CycleEvent& e = watch_.event("worst", worst.time, schedule_.at(worst.time));
  e.criterion = worst.least_criterion;
  e.margin = worst.least_margin;
  if (!settings_.failure_load_at_worst) return;
  if (progress_) progress_(fmt::format("duty cycle: the failure load at the worst moment, t = {:.6g} s", worst.time));
  CycleEvent found = e;
  failure_at_worst(model_, out_, worst, largest_load, found);
  cycle_.events.back() = found;
}

}  // namespace twb
