// What a duty cycle did, in the run's summary lines: its segments and steps, the heat
// balance, and each event (crossings, recoveries, runaways, rests, the worst moment).
#pragma once

#include <chrono>

#include "model/bearing_model.h"
#include "study/operating_schedule.h"
#include "twb/results/cycle_table.h"
#include "twb/study/study_outcome.h"

namespace twb {

// `started`: when the study began (its wall time is the first line's).
void summarize_cycle(const BearingModel& model, const OperatingSchedule& schedule, const CycleHeat& heat,
                     std::chrono::steady_clock::time_point started, StudyOutcome& out);

}  // namespace twb
