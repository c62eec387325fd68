// What the summary after a run says about the model's and the oil's limits
// (twb/model/operating_limits.h): for every run of a study (a speed, a parameter value, a
// sliding film) and every limit, the lightest load whose state exceeds it, and whether
// that state lies on the cool branch below W_d, i.e. the bearing leaves the range where
// its results can be trusted before thermo-viscous distress.
#pragma once

#include <string>
#include <vector>

#include "twb/results/distress_table.h"
#include "twb/results/states_table.h"

namespace twb {

// One line per run and limit exceeded (runs in order, limits in LimitKind order), each
// at the lightest load past it; empty when no state exceeds a limit. A run's parameter
// value is named by its column (e.g. groove_count), "parameter" where none is given; its
// speed in rpm where the scene gave its speeds so (StudyOutcome::speeds_in_rpm).
std::vector<std::string> limit_notes(const std::vector<SolvedState>& states, const std::vector<DistressRow>& distress,
                                     const std::vector<std::string>& parameter_columns = {},
                                     bool speeds_in_rpm = false);

}  // namespace twb
