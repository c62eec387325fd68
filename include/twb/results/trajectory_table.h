// trajectory.csv: the pseudo-time thermal transient after a load step:
//   t_s, T_mean_C, T_max_C, hmin_over_sigma, contact_share, f_eff, load_N, speed_rad_s
// then, for a study of several runs, the columns that tell them apart (the parameter,
// the sliding film); each run's transient starts again at t_s = 0.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "twb/model/bearing_state.h"
#include "twb/results/result_table.h"
#include "twb/scene/scene.h"

namespace twb {

struct TrajectorySample {
  double time = 0.0;  // s of pseudo-time since the step
  BearingState state;
  std::vector<double> parameters;  // as in SolvedState
  std::optional<SlidingFilm> sliding;  // sliding_choice: the configuration
};

// The table trajectory.csv is written from (result_table.h).
ResultTable trajectory_table(const std::vector<TrajectorySample>& samples,
                             const std::vector<std::string>& parameter_columns = {}, bool sliding_column = false);

std::string trajectory_csv(const std::vector<TrajectorySample>& samples,
                           const std::vector<std::string>& parameter_columns = {}, bool sliding_column = false);

}  // namespace twb
