// fold_curve.csv: the fold of the cool branch continued in a second parameter (study
// type distress_curve), one row per point of the curve and one per turn:
//   <parameter>, W_fold_N, fold, T_mean_C, T_max_C, hmin_over_sigma, contact_share, f_eff,
//   W_fold_fine_N, W_fold_extrapolated_N, W_fold_error_N, W_fold_meshes, W_fold_order,
//   W_fold_tolerance_met
// <parameter> is the curve's parameter with its unit (speed_rad_s, friction_coefficient,
// gear_tilt_rad, ambient_C, viscosity_scale, roughness_Rq_m); fold says which fold the row is: "distress" (the branch's
// largest load: W_d), "recovery" (its smallest: the hot branch turning back to the cool
// one), "cusp" (where the two merge and sudden distress ends) or "turn" (the curve turns
// back in the parameter without a cusp). The state columns describe the state at the fold.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "twb/model/bearing_state.h"
#include "twb/model/operating_limits.h"
#include "twb/results/distress_table.h"
#include "twb/results/result_table.h"

namespace twb {

// Which curve a row lies on (the fold column, by fold_name).
enum class FoldKind {
  distress,  // the cool branch's fold: W_d
  recovery,  // the hot branch turning back to the cool one
  cusp,      // where the two merge and sudden distress ends
  turn,      // the curve turns back in the parameter without a cusp
  limit,     // a failure criterion's crossing continued in the parameter (FoldCurveRow::limit)
};

struct FoldCurveRow {
  double parameter = 0.0;  // SI
  FoldKind fold = FoldKind::distress;
  LimitKind limit = LimitKind::oil_temperature;  // the criterion, on a limit curve
  BearingState state;  // at the fold; state.load is W_fold
  // A family of curves (study.family): this curve's value of the family parameter (SI).
  std::optional<double> member;
  // The fold's discretization error (study.error_estimate: richardson): the same fold on
  // the mesh refined by two, the Richardson extrapolation and its error bar (N); absent
  // for cusps and turns, and where the refined fold was not found.
  std::optional<double> fine_load, extrapolated_load, discretization_error;
  // With a tolerance (study.tolerance): the meshes the fold was located on, the order they
  // show and whether the bar meets the tolerance.
  LoadConvergence convergence;
};

// "distress", "recovery", "cusp", "turn", or the criterion's limit_name: the fold column.
std::string fold_name(const FoldCurveRow& row);

// The table fold_curve.csv is written from (result_table.h).
ResultTable fold_curve_table(const std::vector<FoldCurveRow>& rows, const std::string& parameter_column,
                             const std::string& family_column = {});

// parameter_column as above; ambient_C converts the SI (K) values it holds. family_column
// (e.g. friction_coefficient), when not empty, comes first and holds each row's member.
std::string fold_curve_csv(const std::vector<FoldCurveRow>& rows, const std::string& parameter_column,
                           const std::string& family_column = {});

}  // namespace twb
