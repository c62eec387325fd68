// Runs the study a scene asks for on a model and collects what it writes (twb/study/
// study_outcome.h); twb::Bearing::run_study is its public face.
#pragma once

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"

namespace twb {

class SearchJournal;

// Throws std::invalid_argument for a study this version cannot run. `journal`: where each
// finished search is written at once and, on resume, read instead of run
// (search_journal.h; twb::Bearing::run_into keeps one in its results directory).
StudyOutcome run_study(BearingModel& model, const ProgressReport& progress, const RunOptions& options = {},
                       const SearchJournal* journal = nullptr);

}  // namespace twb
