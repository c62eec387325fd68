// trajectory.csv: the bearing along a march in time: the pseudo-time thermal transient
// after a load step (the transient study, the runaway step of a search) or a duty cycle
// in real time:
//   t_s, T_mean_C, T_max_C, hmin_over_sigma, contact_share, f_eff, load_N, speed_rad_s,
//   torque_Nm, fluid_share, regime, heat_generated_W, heat_to_ambient_W
// then, for a duty cycle, the schedule's ambient_C and tilt_rad at that time and the
// least_margin with its least_margin_criterion (TrajectorySample) and stop_reaction_N
// (empty without the gear's stop), and for a study of
// several runs the columns that tell them apart (the parameter, the sliding film); each
// run's transient starts again at t_s = 0.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "twb/model/bearing_state.h"
#include "twb/model/operating_limits.h"
#include "twb/results/result_table.h"
#include "twb/scene/scene.h"

namespace twb {

// Who carries the load (docs/physics.md section 19): the oil film alone (the asperities
// carry less than 1 %), the asperities almost alone (the film less than 10 %), or both.
// at_rest: unloaded and standing still (load and speed zero), the washer and gear held
// where they came to rest (docs/physics.md section 19): no film carries anything.
enum class Regime { full_film, mixed, boundary, at_rest };
Regime regime_of(const BearingState& state);
std::string_view regime_name(Regime regime);

struct TrajectorySample {
  double time = 0.0;  // s since the step (pseudo-time), or the schedule's zero (real time)
  BearingState state;
  std::vector<double> parameters;  // as in SolvedState
  std::optional<SlidingFilm> sliding;  // sliding_choice: the configuration
  // A duty cycle's: the schedule's ambient (K) and gear tilt (rad) at that time, and the
  // least failure criterion's margin as a fraction of its allowance (docs/physics.md
  // section 19: 1 at rest in the ambient, 0 on the limit, negative past it), none where
  // the scene applies no criterion.
  std::optional<double> ambient, tilt;
  std::optional<double> least_margin;
  std::optional<LimitKind> least_criterion;
};

// The table trajectory.csv is written from (result_table.h); `cycle`: with a duty
// cycle's columns.
ResultTable trajectory_table(const std::vector<TrajectorySample>& samples,
                             const std::vector<std::string>& parameter_columns = {}, bool sliding_column = false,
                             bool cycle = false);

std::string trajectory_csv(const std::vector<TrajectorySample>& samples,
                           const std::vector<std::string>& parameter_columns = {}, bool sliding_column = false);

}  // namespace twb
