// sliding.csv: which film slides (MODEL.md section 2, the paper's "Component Rotational
// Speed"): both configurations at every load of the grid, the one of lower friction
// torque marked chosen. One row per (speed, load, configuration):
//   speed_rad_s, load_N, sliding, film_area_m2, fluid_force_N, fluid_share, contact_share,
//   torque_Nm, f_eff, hmin_over_sigma, T_mean_C, chosen
#pragma once

#include <string>
#include <vector>

#include "twb/results/states_table.h"

namespace twb {

struct SlidingRow {
  SolvedState solved;      // solved.sliding names the configuration
  double film_area = 0.0;  // m², the sliding film's annulus
  bool chosen = false;     // the lowest friction torque at this speed and load
};

std::string sliding_csv(const std::vector<SlidingRow>& rows);

}  // namespace twb
