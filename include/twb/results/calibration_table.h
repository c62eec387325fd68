// calibration.csv, calibration_correlation.csv and calibration_points.csv (study type
// calibration, docs/physics.md section 18).
//
// calibration.csv, one row per fitted input:
//   parameter, parameter_unit, start, lower, upper, fitted, sd, at_bound
// fitted the least-squares value (SI), sd its standard deviation from the covariance at
// the fit (empty where the data do not determine it), at_bound lower, upper or empty.
//
// calibration_correlation.csv, one row per pair of fitted inputs (each pair once, and
// each input with itself):
//   parameter_a, parameter_b, covariance, correlation
//
// calibration_points.csv, one row per measured value:
//   point, line, load_N, speed_rad_s, quantity, measured, at_start, fitted, sd, residual
// point: the measured point's number (1 = the data's first row), line: its line in the
// data file; quantity: torque_Nm, f_eff, T_mean_C or T_max_C, the values in its unit;
// sd: the reading's standard deviation (empty where the fit is relative), residual
// (fitted − measured)/sd, or where the fit is relative (fitted − measured)/|measured|
// (a temperature's over its rise above the ambient).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "twb/results/result_table.h"

namespace twb {

struct CalibrationRow {
  std::string parameter, parameter_unit;
  double start = 0.0, lower = 0.0, upper = 0.0, fitted = 0.0;
  std::optional<double> sd;
  std::string at_bound;
};

struct CorrelationRow {
  std::string parameter_a, parameter_b;
  double covariance = 0.0, correlation = 0.0;
};

struct CalibrationPointRow {
  long point = 0, line = 0;
  double load = 0.0, speed = 0.0;  // N, rad/s
  std::string quantity;
  double measured = 0.0, at_start = 0.0, fitted = 0.0;
  std::optional<double> sd;
  double residual = 0.0;
};

ResultTable calibration_table(const std::vector<CalibrationRow>& rows);
ResultTable correlation_table(const std::vector<CorrelationRow>& rows);
ResultTable calibration_points_table(const std::vector<CalibrationPointRow>& rows);

}  // namespace twb
