// sliding.csv: which film slides (docs/physics.md section 2, the paper's "Component Rotational
// Speed"): both configurations at every load of the grid, the one of lower friction
// torque marked chosen. One row per (speed, load, configuration):
//   speed_rad_s, load_N, sliding, film_area_m2, fluid_force_N, fluid_share, contact_share,
//   torque_Nm, f_eff, hmin_over_sigma, T_mean_C, chosen
#pragma once

#include <string>
#include <vector>

#include "twb/results/states_table.h"
#include "twb/results/result_table.h"

namespace twb {

struct SlidingRow {
  SolvedState solved;      // solved.sliding names the configuration
  double film_area = 0.0;  // m², the sliding film's annulus
  bool chosen = false;     // the lowest friction torque at this speed and load
};

// The table sliding.csv is written from (result_table.h).
ResultTable sliding_table(const std::vector<SlidingRow>& rows);

std::string sliding_csv(const std::vector<SlidingRow>& rows);

}  // namespace twb
