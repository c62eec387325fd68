// Runs the study a scene asks for and collects its solved states.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "twb/model/bearing_model.h"
#include "twb/results/run_record.h"
#include "twb/results/states_table.h"

namespace twb {

struct StudyOutcome {
  std::vector<SolvedState> states;
  bool solver_failed = false;  // a state the study needed could not be solved
  std::string message;
  RunTimings timings;
};

using ProgressReport = std::function<void(const std::string&)>;

// Throws std::invalid_argument for a study type this version cannot run.
StudyOutcome run_study(BearingModel& model, const ProgressReport& progress);

}  // namespace twb
