// distress.csv: one row per distress search :
//   speed_rad_s, <param>, sliding, W_fail_N, criterion, W_d_N, bracket_low_N, bracket_high_N,
//   fold_N, W_d_fine_N, W_d_extrapolated_N, W_d_error_N, W_oil_temperature_N,
//   W_oil_peak_temperature_N, W_material_temperature_carrier_N, ..._washer_N, ..._gear_N,
//   W_film_ratio_N, the same six as W_<criterion>_error_N, failure, method
// W_fail is where the bearing fails: the least of W_d and the loads where the branch
// continued from the start first crosses a failure criterion (docs/physics.md section 8);
// criterion names the one that sets it.
// <param> is the study's second axis (e.g. friction_coefficient), sliding the film that
// slides (sliding_choice); each column is left out when the study has none. A value that does not exist (no fold on the branch,
// no distress below the highest load searched) is an empty cell, never NaN.
#pragma once

#include <optional>
#include <string>
#include <vector>
#include "twb/model/operating_limits.h"
#include "twb/results/result_table.h"
#include "twb/scene/scene.h"

namespace twb {

// How a distress search decided its row (docs/model.md, "Distress on the bearing").
enum class DistressVerdict {
  undecided,        // no verdict: the search failed first (its message says why)
  fold_proven,      // "runaway; fold at …, proven by transients: …"
  bisection,        // "runaway bracketed by bisection; …" (no fold, or the dynamics disagree)
  gradual_heating,  // "no fold up to … (gradual heating)": the branch reaches load_end
  no_heating,       // no fold up to load_end and nothing to produce thermo-viscous distress
                    // (no thermal effect, or an oil whose viscosity does not depend on temperature)
  steady_fold,      // no thermal effect: the steady branch's fold (or end) alone, no transient
  fold_only,        // the fold alone, as the error estimate's refined meshes ask
  settled,          // "no distress up to …: every load step settled on the branch"
  no_bracket,       // the transients gave no bracket
  solver_failure,   // a state the search needed could not be solved
  bounded,          // "no fold up to … (not searched further: …)": the branch was searched only
                    // so far past the first failure criterion (study.search_past_failure)
};

// What sets W_fail (docs/physics.md section 8): thermo-viscous distress, or the first
// failure criterion (kFailureCriteria) crossed on the branch.
struct FailureCriterion {
  bool distress = true;
  LimitKind limit = LimitKind::oil_temperature;  // the criterion crossed, where not distress
  static FailureCriterion thermo_viscous_distress() { return {}; }
  static FailureCriterion crossing(LimitKind kind) { return {false, kind}; }
  bool operator==(const FailureCriterion&) const = default;
};
// A criterion's own load column: W_<criterion>{suffix}_N, the body's colon an underscore
// (W_material_temperature_washer_N, W_oil_peak_temperature_error_N).
std::string criterion_column(LimitKind kind, const char* suffix = "");

// "distress", or the criterion's limit_name: distress.csv's criterion column.
std::string criterion_name(const FailureCriterion& criterion);

// How a mesh-converged load was reached (study.tolerance; docs/physics.md section 8, "To a
// requested accuracy"): the meshes it was solved on, the order they show where three do,
// and whether its bar meets the tolerance (none without a tolerance).
struct LoadConvergence {
  std::string meshes;  // "9x66 17x132 33x264", the scene's first
  std::optional<double> order;
  std::optional<bool> tolerance_met;
  std::string why_unmet;  // where not met: the bar reached and what ended the sequence
  bool operator==(const LoadConvergence&) const = default;
};

// "on 9x66 17x132 33x264, observed order 1.78" (without the order where none is seen);
// empty where the load had no mesh sequence.
std::string convergence_phrase(const LoadConvergence& c);

struct DistressRow {
  double speed = 0.0;                     // rad/s
  std::vector<double> parameters;         // the study's axes' values (SI, run_axes.h), if any
  std::optional<double> distress_load;    // W_d, N
  std::optional<double> bracket_low;      // highest load whose step settled, N
  std::optional<double> bracket_high;     // lowest load whose step ran away, N
  std::optional<double> fold_load;        // turning point of the steady branch, N
  std::string method;                     // how W_d was decided (docs/model.md, "Distress on the bearing")
  std::optional<SlidingFilm> sliding;     // sliding_choice: the configuration
  // study.error_estimate: richardson (docs/model.md): the fold on the mesh refined
  // by two, the extrapolated W_d and its error bar.
  std::optional<double> fine_fold_load;      // N
  std::optional<double> extrapolated_load;   // N
  std::optional<double> discretization_error;  // N
  // Where the bearing fails: W_fail, the least of W_d and the criteria's loads, and the
  // criterion that sets it (none without a failure load).
  std::optional<double> failure_load;  // N
  std::optional<FailureCriterion> criterion;
  // Each failure criterion's first crossing on the branch (kFailureCriteria order), N;
  // empty where it is not crossed up to the branch's end or does not apply.
  PerCriterion<std::optional<double>> criterion_loads;
  // "fails at 307.6 N by the oil's peak temperature (no thermo-viscous distress up to 4000 N)".
  std::string failure;
  // study.error_estimate: richardson: each crossing's error bar (the crossing again on the
  // mesh refined by two, as W_d's), and W_fail's mesh-converged value and error bar (W_d's
  // or its criterion's), N.
  PerCriterion<std::optional<double>> criterion_errors;
  std::optional<double> failure_extrapolated, failure_error;
  // study.tolerance: each crossing's mesh-converged load (W_fail's is failure_extrapolated,
  // W_d's extrapolated_load), and how W_d's and W_fail's were reached.
  PerCriterion<std::optional<double>> criterion_extrapolated;
  LoadConvergence fold_convergence, failure_convergence;
  // The verdict `method` words (with its numbers): what studies and tests read.
  DistressVerdict verdict = DistressVerdict::undecided;
};

// The load where the criterion is crossed (kFailureCriteria order), if it is.
std::optional<double> criterion_load(const DistressRow& row, LimitKind kind);

// The table distress.csv is written from (result_table.h).
ResultTable distress_table(const std::vector<DistressRow>& rows, const std::vector<std::string>& parameter_columns,
                           bool sliding_column = false);

// parameter_columns: the study's axes, e.g. "friction_coefficient", "gear_tilt_rad"; none
// for a single run.
std::string distress_csv(const std::vector<DistressRow>& rows, const std::vector<std::string>& parameter_columns,
                         bool sliding_column = false);

}  // namespace twb
