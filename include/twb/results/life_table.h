// A washer's life (study type life, docs/physics.md section 20), life.csv: the washer as
// it wears, at every reported time of the slow time,
//   t_h, worn_depth_rest_max_um, worn_depth_rest_mean_um, worn_volume_rest_mm3, rq_rest_um,
//   worn_depth_turn_max_um, worn_depth_turn_mean_um, worn_volume_turn_mm3, rq_turn_um,
//   wear_rate_rest_um_h, wear_rate_turn_um_h, torque_Nm, f_eff, T_max_C,
//   hmin_over_sigma, contact_share, W_fail_N, failure_criterion, event
// for the face at rest in the load frame and the turning face of the sliding film (the
// deepest depth, the area mean, the volume worn off and the Rq; the fastest rate), the failure
// load of the washer worn so far at the operating speed and its criterion (with
// study.failure_load; its search is distress.csv's row of that time), and how it
// ended: "end" (the duration reached), "wear_allowance" (a face reached
// limits.wear_depth), "failure" (the failure load come down to the operating load) or
// "distress" (the steady bearing lost at the operating load: the march cannot go on).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "twb/results/distress_table.h"
#include "twb/results/result_table.h"

namespace twb {

// The time column of life.csv, and the parameter column (run_axes.h) of a life's states
// and failure searches.
inline constexpr const char* kLifeTimeColumn = "t_h";

// One face's wear at a time: deepest and mean depth (m), the volume worn off (m³) and the
// face's Rq (m; as it runs in, the root of its area mean of Rq²).
struct FaceWear {
  double deepest = 0.0, mean = 0.0, volume = 0.0, rq = 0.0;
};

struct LifeRow {
  double time = 0.0;  // s
  FaceWear rest, turn;
  double rest_rate = 0.0, turn_rate = 0.0;  // m/s, where each face wears fastest
  double torque = 0.0, f_eff = 0.0;
  double max_temperature = 0.0;  // K, the hottest film node
  double hmin_over_sigma = 0.0, contact_share = 0.0;
  std::optional<double> failure_load;  // N, W_fail at that time
  std::optional<FailureCriterion> failure_criterion;
  std::string event;  // empty, or how the life ended there
};

ResultTable life_table(const std::vector<LifeRow>& rows);

}  // namespace twb
