// A washer's life (study type life, docs/physics.md section 20): the worn depths
// integrated in the wear's slow time by IDA at the operating point, everything else of
// the bearing quasi-steady ([W4]), the washer reported every `report_every`, until the
// duration, the wear allowance (located between two steps) or distress (the steady
// bearing lost as the faces wear: IDA cannot go on).
#pragma once

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"

namespace twb {

void run_life(BearingModel& model, StudyOutcome& out, const ProgressReport& progress);

}  // namespace twb
