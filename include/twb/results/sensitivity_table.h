// sensitivity.csv (study type sensitivity, docs/physics.md section 16): each reported
// quantity's derivative with respect to each input, one row per pair:
//   quantity, value, parameter, parameter_value, parameter_unit, derivative, elasticity, step
// quantity: torque_Nm, f_eff, T_mean_C, T_max_C, hmin_over_sigma, fluid_share of the state at
// the operating point; with a load range, W_d_N (the fold's load), W_<criterion>_N (each
// criterion's crossing, as distress.csv names it) and W_fail_N (the rows of the one that
// sets the failure load).
// value is the quantity's (°C for temperatures), parameter the input's scene path and
// parameter_value its SI value in parameter_unit; derivative is d quantity / d parameter in
// their SI units (a temperature's per kelvin); elasticity the relative change of the
// quantity per relative change of the input, (p/q)·dq/dp, a temperature's relative to its
// rise above the ambient, and a temperature input's p the washer's mean rise above the
// ambient (docs/physics.md section 16); step the input's difference step δ (SI).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "twb/results/result_table.h"

namespace twb {

struct SensitivityRow {
  std::string quantity;
  double value = 0.0;  // the quantity as written (°C for temperatures)
  std::string parameter;
  double parameter_value = 0.0;  // SI
  std::string parameter_unit;
  double derivative = 0.0;  // SI per SI
  std::optional<double> elasticity;  // absent where the quantity or the input is zero
  double step = 0.0;  // SI
};

ResultTable sensitivity_table(const std::vector<SensitivityRow>& rows);

}  // namespace twb
