// Runs the study a scene asks for on a model and collects what it writes (twb/study/
// study_outcome.h); twb::Bearing::run_study is its public face.
#pragma once

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"

namespace twb {

class SearchJournal;
class SearchScheduler;

// What twb's command adds to RunOptions: where each finished search is written at once
// and, on resume, read instead of run (search_journal.h), and where the study's
// independent searches run (search_scheduler.h: MPI ranks, a slice of a job array; none:
// on RunOptions::threads threads here).
struct StudyPlumbing {
  const SearchJournal* journal = nullptr;
  SearchScheduler* scheduler = nullptr;
};

// Throws std::invalid_argument for a study this version cannot run.
StudyOutcome run_study(BearingModel& model, const ProgressReport& progress, const RunOptions& options = {},
                       const StudyPlumbing& plumbing = {});

}  // namespace twb
