// A washer's life through a duty cycle repeated (study type life with a schedule,
// docs/physics.md section 20, "A repeated duty cycle"): the cycle marched in real time
// with the depths frozen gives the depth each node loses per cycle, Δd(d); the depths
// follow ∂d/∂t = Δd(d)/T over the life by Heun's pair (Euler its error estimate), a step
// a whole number of cycles set by the depth tolerance, every cycle marched where the
// tolerance asks for it. Each march starts where the one before ended (the cycles jumped
// are taken as the last one marched). The life ends at the duration's last whole cycle,
// at the wear allowance, in the first cycle that passes a failure criterion or runs
// away (each located to its cycle), or where the failure load at the cycle's worst
// moment comes down to the load there.
#pragma once

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"

namespace twb {

void run_cycle_life(BearingModel& model, StudyOutcome& out, const ProgressReport& progress);

}  // namespace twb
