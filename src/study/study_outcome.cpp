#include "twb/study/study_outcome.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "twb/results/run_axes.h"
#include "study/study_kind.h"
#include "twb/scene/scene_loader.h"

namespace twb {

std::vector<NamedTable> study_tables(const StudyOutcome& out, StudyType type) {
  std::vector<NamedTable> tables;
  tables.push_back({"states", states_table(out.states, out.parameter_columns, out.sliding_column)});
  study_kind(type).add_tables(out, tables);
  // A trajectory the type's own tables leave out: a transient's march, the runaway's first
  // steps of a sweep's searches.
  const bool named = std::any_of(tables.begin(), tables.end(), [](const NamedTable& t) { return t.name == "trajectory"; });
  if (!named && !out.trajectory.empty())
    tables.push_back({"trajectory", trajectory_table(out.trajectory, out.parameter_columns, out.sliding_column)});
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

bool has_independent_searches(const Study& study) { return study_kind(study.type()).independent_searches(study); }

bool spreads_over_ranks(const Study& study) {
  return has_independent_searches(study) || study_kind(study.type()).spreads_over_ranks(study);
}

void check_continuable(const Study& study, std::string_view asked_by) {
  if (!study_kind(study.type()).continues_from)
    throw std::invalid_argument(fmt::format("{} goes on with a duty cycle from where an earlier one ended; this "
                                            "scene's study is a {}",
                                            asked_by, scene_name(study.type())));
}

CycleState cycle_to_continue(const Study& study, const std::string& from, const std::string& out,
                             std::string_view asked_by) {
  check_continuable(study, asked_by);
  std::error_code same_error;
  if (!out.empty() && std::filesystem::equivalent(out, from, same_error))
    throw std::invalid_argument(fmt::format("{} {}: the continued part's results go to another directory, or its "
                                            "end state would replace the one it starts from",
                                            asked_by, from));
  return read_cycle_state((std::filesystem::path(from) / "cycle_end_state.json").string());
}

}  // namespace twb
