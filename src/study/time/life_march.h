// A washer's life (study type life, docs/physics.md section 20): the worn depths
// integrated in the wear's slow time by IDA at the operating point, everything else of
// the bearing quasi-steady ([W4]), the washer reported every `report_every`, until the
// duration, the wear allowance (located between two steps) or distress (the steady
// bearing lost as the faces wear: IDA cannot go on).
#pragma once

#include <string>

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"

namespace twb {

// At one operating point, or through the scene's repeated duty cycle (cycle_life.h).
void run_life(BearingModel& model, StudyOutcome& out, const ProgressReport& progress);

// The life's message and summary from its rows: `subject` ("life at 150 N"), how it
// ended, each face's wear at the end, the failure load new and at the end.
void summarize_life(StudyOutcome& out, const std::string& subject, const std::string& ending);

}  // namespace twb
