// trajectory.csv: the pseudo-time thermal transient after a load step (issue contract):
//   t_s, T_mean_C, T_max_C, hmin_over_sigma, contact_share, f_eff, load_N
#pragma once

#include <string>
#include <vector>

#include "twb/model/bearing_model.h"

namespace twb {

struct TrajectorySample {
  double time = 0.0;  // s of pseudo-time since the step
  BearingState state;
};

std::string trajectory_csv(const std::vector<TrajectorySample>& samples);

}  // namespace twb
