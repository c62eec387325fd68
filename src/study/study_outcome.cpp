#include "twb/study/study_outcome.h"

#include <fmt/format.h>

#include "twb/results/run_axes.h"
#include "twb/scene/scene_loader.h"


namespace twb {

std::vector<NamedTable> study_tables(const StudyOutcome& out, StudyType type) {
  const std::vector<std::string>& parameter = out.parameter_columns;
  const bool sliding = out.sliding_column;
  std::vector<NamedTable> tables;
  tables.push_back({"states", states_table(out.states, parameter, sliding)});
  if (type != StudyType::point && type != StudyType::transient && type != StudyType::sensitivity &&
      type != StudyType::reliability && type != StudyType::calibration && type != StudyType::duty_cycle)
    tables.push_back({"distress", distress_table(out.distress, parameter, sliding)});
  if (type == StudyType::sliding_choice) tables.push_back({"sliding", sliding_table(out.sliding)});
  if (type == StudyType::distress_curve)
    tables.push_back({"fold_curve", fold_curve_table(out.fold_curve, out.fold_curve_column, parameter.empty() ? std::string() : parameter.front())});
  if ((type == StudyType::sensitivity || type == StudyType::reliability || type == StudyType::duty_cycle) &&
      !out.distress.empty())
    tables.push_back({"distress", distress_table(out.distress, parameter, sliding)});
  if (type == StudyType::sensitivity) tables.push_back({"sensitivity", sensitivity_table(out.sensitivity)});
  if (type == StudyType::reliability) {
    tables.push_back({"reliability", reliability_table(out.reliability)});
    tables.push_back({"design_point", design_point_table(out.design_points)});
  }
  if (type == StudyType::calibration) {
    tables.push_back({"calibration", calibration_table(out.calibration)});
    tables.push_back({"calibration_correlation", correlation_table(out.correlations)});
    tables.push_back({"calibration_points", calibration_points_table(out.calibration_points)});
  }
  if (type == StudyType::duty_cycle) {
    tables.push_back({"trajectory", trajectory_table(out.trajectory, {}, false, true)});
    tables.push_back({"cycle_events", cycle_events_table(out.cycle_events)});
  } else if (!out.trajectory.empty()) {
    tables.push_back({"trajectory", trajectory_table(out.trajectory, parameter, sliding)});
  }
  return tables;
}

std::vector<std::string> summary_lines(const StudyOutcome& outcome) {
  std::vector<std::string> lines;
  for (const DistressRow& d : outcome.distress) {
    const std::string where =
        fmt::format("{}{}{}", speed_text(d.speed, outcome.speeds_in_rpm), run_axes_text(outcome.parameter_columns, d.parameters),
                    d.sliding ? ", sliding " + std::string(scene_name(*d.sliding)) : "");
    std::string distress = "none";
    if (d.distress_load && d.extrapolated_load && d.discretization_error) {
      const LoadConvergence& c = d.fold_convergence;
      distress = fmt::format("W_d = {:.1f} ± {:.1f} N mesh-converged ({}); {:.2f} N on the scene's mesh",
                             *d.extrapolated_load, *d.discretization_error,
                             c.meshes.empty()
                                 ? fmt::format("Richardson, {:.2f} N on the mesh refined by two", *d.fine_fold_load)
                                 : convergence_phrase(c),
                             *d.distress_load);
    } else if (d.distress_load) {
      distress = fmt::format("W_d = {:.2f} N on the scene's mesh", *d.distress_load);
    }
    lines.push_back(fmt::format("distress at {}: {} ({})", where, distress, d.method));
    if (!d.failure.empty()) lines.push_back(fmt::format("failure at {}: {}", where, d.failure));
    // A load whose bar the mesh sequence could not bring within the tolerance: said, not
    // hidden behind a coarse number.
    const auto warn = [&](const char* what, const LoadConvergence& c) {
      if (c.tolerance_met && !*c.tolerance_met)
        lines.push_back(fmt::format("warning: at {}, {} is not within the tolerance: {}", where, what, c.why_unmet));
    };
    warn("W_fail", d.failure_convergence);
    if (!d.criterion || !d.criterion->distress) warn("W_d", d.fold_convergence);  // else said as W_fail
  }
  lines.insert(lines.end(), outcome.summary.begin(), outcome.summary.end());
  return lines;
}

bool has_independent_searches(const Study& study) {
  if (study.type == StudyType::distress_map) return study.map_method == MapMethod::search;
  return study.type == StudyType::load_sweep || study.type == StudyType::sliding_choice;
}

bool spreads_over_ranks(const Study& study) {
  return has_independent_searches(study) || (study.type == StudyType::reliability && study.max_samples > 0);
}

}  // namespace twb
