// Runs the study a scene asks for on a model and collects what it writes (twb/study/
// study_outcome.h); twb::Bearing::run_study is its public face.
#pragma once

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"

namespace twb {

// Throws std::invalid_argument for a study this version cannot run.
StudyOutcome run_study(BearingModel& model, const ProgressReport& progress, const RunOptions& options = {});

}  // namespace twb
