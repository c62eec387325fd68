// states.csv: one row per solved state, units in the column names.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "twb/model/bearing_state.h"
#include "twb/model/film_fields.h"
#include "twb/results/result_table.h"
#include "twb/scene/scene.h"

namespace twb {

// The steady branch a state lies on: cool (continued from the lightest load, before
// distress) or hot (past distress: where the runaway settled and continued from
// there); none where a study follows no branch (point, transient).
enum class Branch { none, cool, hot };
// As states.csv writes it: "cool", "hot", or empty.
inline const char* branch_name(Branch b) { return b == Branch::cool ? "cool" : b == Branch::hot ? "hot" : ""; }

struct SolvedState {
  BearingState state;
  bool converged = false;
  long iterations = 0;
  double residual = 0.0;
  double wall_ms = 0.0;
  // Which run of a study the state belongs to, when the study runs several: the values
  // of its axes (SI, run_axes.h) and the film that slides ("carrier_washer", "washer_gear").
  std::vector<double> parameters;
  std::optional<SlidingFilm> sliding;  // sliding_choice: the configuration
  // Which steady branch a load sweep found the state on (states.csv's `branch`).
  Branch branch = Branch::none;
  // The discretization error of the reported quantities (a point study with
  // study.error_estimate: richardson): the state again on the mesh refined by two, each
  // quantity's Richardson extrapolation and its error bar (richardson.h), in the order of
  // kMeshErrorQuantities: (extrapolated, error) pairs; empty without the estimate.
  std::vector<double> mesh_errors;
  // Film 1 and film 2 on their polar grids when the scene asks for them
  // (output.fields); empty otherwise. Written by fields_table.h.
  std::vector<FilmFields> fields;
};

// The quantities a state's error bar covers, as states.csv names them (their columns
// <name>_extrapolated and <name>_error follow the state's own where a state has them).
inline constexpr const char* kMeshErrorQuantities[] = {"T_mean_C", "T_max_C", "T_oil_peak_C", "hmin_over_sigma",
                                                       "torque_Nm", "f_eff"};
// How many of them, from the first, are temperatures (their offsets counted from the ambient).
inline constexpr std::size_t kMeshErrorTemperatures = 3;
// Those quantities of a state, in that order (temperatures in degC).
std::vector<double> mesh_error_quantities(const BearingState& state);

// The table states.csv is written from (result_table.h).
ResultTable states_table(const std::vector<SolvedState>& rows, const std::vector<std::string>& parameter_columns = {},
                         bool sliding_column = false);

// parameter_columns (the study's axes, e.g. "friction_coefficient"; none for a single
// run) and sliding_column add the columns that tell a study's runs apart, after speed_rad_s.
std::string states_csv(const std::vector<SolvedState>& rows, const std::vector<std::string>& parameter_columns = {},
                       bool sliding_column = false);

// The short table printed after a run.
std::string states_summary(const std::vector<SolvedState>& rows);

}  // namespace twb
