#include "study/time/duty_cycle.h"

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "study/time/cycle_start.h"
#include "study/time/cycle_summary.h"
#include "study/time/duty_cycle_march.h"
#include "study/time/operating_schedule.h"
#include "study/study_support.h"
#include "twb/results/cycle_state.h"
#include "twb/scene/scene_loader.h"

namespace twb {

// The cycle's steps are duty_cycle_march.h's.
void run_duty_cycle(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, const CycleState* start) {
  out.own_part<DutyCycleOutcome>();  // first: cycle_events.csv is written (empty) where the cycle does not start
  const auto t0 = std::chrono::steady_clock::now();
  // The scene's schedule, with a point where an unloaded washer's speed turns back.
  const DutyCycleSettings& settings = std::get<DutyCycleSettings>(model.scene().study.settings);
  const std::vector<SchedulePoint>& points = settings.schedule;
  const OperatingSchedule schedule(OperatingSchedule::with_rests(points));
  const NewtonSettings newton = newton_settings(model.scene());
  const std::string bearing = bearing_of(describe_scene(model.scene()));

  // The start: the steady state at the schedule's start, or where the cycle continued
  // from ended.
  std::optional<std::vector<double>> begun = cycle_start(model, schedule, newton, start, bearing, out, progress);
  if (!begun) return;
  DutyCycleMarch march(model, schedule, settings, std::move(*begun), out, progress);
  if (!march.run(bearing)) return;
  summarize_cycle(points.size() - 1, schedule, t0, out);
  out.timings.transients += 1;
}

}  // namespace twb
