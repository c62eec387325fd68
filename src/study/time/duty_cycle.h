// A duty cycle (study type duty_cycle, docs/physics.md section 19): the bearing followed
// through a schedule of load, speed, ambient and gear tilt in real time, from the
// steady state at the schedule's start. IDA marches the bodies' heat (their physical
// capacities ρ·c·t) segment by segment, restarted at every point of the schedule where
// the inputs' rates jump; every failure criterion's margin is watched along the way
// (each crossing and recovery located in time), the thermo-viscous runaway recognised
// as the trajectory's blow-up (the slowest thermal mode grown unstable while the
// temperatures accelerate), and the cycle's worst moment reported with the failure load
// at that moment's speed, ambient and tilt.
#pragma once

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"

namespace twb {

// `start`: an earlier cycle's end to go on from (RunOptions::cycle_start), else none.
void run_duty_cycle(BearingModel& model, StudyOutcome& out, const ProgressReport& progress,
                    const CycleState* start = nullptr);

}  // namespace twb
