// What a duty cycle did, in the run's summary lines: its segments and steps, the heat
// balance, and each event (crossings, recoveries, runaways, rests, the worst moment).
#pragma once

#include <chrono>
#include <cstddef>

#include "study/time/operating_schedule.h"
#include "twb/study/study_outcome.h"

namespace twb {

// From out's trajectory, and its DutyCycleOutcome's heat balance (set) and events.
// `segments`: the scene's schedule's (not counting the points the march adds where a
// washer rests); `started`: when the study began (its wall time is the first line's).
void summarize_cycle(std::size_t segments, const OperatingSchedule& schedule,
                     std::chrono::steady_clock::time_point started, StudyOutcome& out);

}  // namespace twb
