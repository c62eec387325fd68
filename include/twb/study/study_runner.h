// Runs the study a scene asks for and collects what it writes: solved states, distress
// rows and the transient's trajectory.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "twb/model/bearing_model.h"
#include "twb/results/distress_table.h"
#include "twb/results/run_record.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"

namespace twb {

struct StudyOutcome {
  std::vector<SolvedState> states;
  std::vector<DistressRow> distress;  // load_sweep, distress_map
  std::string parameter_column;       // distress_map's second axis, e.g. "friction_coefficient"
  std::vector<TrajectorySample> trajectory;  // transient; load_sweep: the first step past distress
  bool solver_failed = false;  // a state the study needed could not be solved
  std::string message;
  RunTimings timings;
};

using ProgressReport = std::function<void(const std::string&)>;

// Throws std::invalid_argument for a study this version cannot run.
StudyOutcome run_study(BearingModel& model, const ProgressReport& progress);

}  // namespace twb
