// distress.csv: one row per distress search :
//   speed_rad_s, <param>, sliding, W_d_N, bracket_low_N, bracket_high_N, fold_N,
//   W_d_fine_N, W_d_extrapolated_N, W_d_error_N, method
// <param> is the study's second axis (e.g. friction_coefficient), sliding the film that
// slides (sliding_choice); each column is left out when the study has none. A value that does not exist (no fold on the branch,
// no distress below the highest load searched) is an empty cell, never NaN.
#pragma once

#include <optional>
#include <string>
#include <vector>
#include "twb/results/result_table.h"

namespace twb {

struct DistressRow {
  double speed = 0.0;                     // rad/s
  std::optional<double> parameter;        // the second axis' value (SI), if any
  std::optional<double> distress_load;    // W_d, N
  std::optional<double> bracket_low;      // highest load whose step settled, N
  std::optional<double> bracket_high;     // lowest load whose step ran away, N
  std::optional<double> fold_load;        // turning point of the steady branch, N
  std::string method;                     // how W_d was decided (docs/model.md, "Distress on the bearing")
  std::string sliding;                    // sliding_choice: "carrier_washer" or "washer_gear"
  // study.error_estimate: richardson (docs/model.md): the fold on the mesh refined
  // by two, the extrapolated W_d and its error bar.
  std::optional<double> fine_fold_load;      // N
  std::optional<double> extrapolated_load;   // N
  std::optional<double> discretization_error;  // N
};

// The table distress.csv is written from (result_table.h).
ResultTable distress_table(const std::vector<DistressRow>& rows, const std::string& parameter_column,
                           bool sliding_column = false);

// parameter_column: e.g. "friction_coefficient", "gear_tilt_rad"; empty for none.
std::string distress_csv(const std::vector<DistressRow>& rows, const std::string& parameter_column,
                         bool sliding_column = false);

}  // namespace twb
