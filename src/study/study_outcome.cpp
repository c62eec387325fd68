#include "twb/study/study_outcome.h"

namespace twb {

std::vector<NamedTable> study_tables(const StudyOutcome& out, StudyType type) {
  const std::string& parameter = out.parameter_column;
  const bool sliding = out.sliding_column;
  std::vector<NamedTable> tables;
  tables.push_back({"states", states_table(out.states, parameter, sliding)});
  if (type != StudyType::point && type != StudyType::transient)
    tables.push_back({"distress", distress_table(out.distress, parameter, sliding)});
  if (type == StudyType::sliding_choice) tables.push_back({"sliding", sliding_table(out.sliding)});
  if (type == StudyType::distress_curve)
    tables.push_back({"fold_curve", fold_curve_table(out.fold_curve, out.fold_curve_column, parameter)});
  if (!out.trajectory.empty()) tables.push_back({"trajectory", trajectory_table(out.trajectory, parameter, sliding)});
  return tables;
}

bool has_independent_searches(StudyType type) {
  return type == StudyType::load_sweep || type == StudyType::distress_map || type == StudyType::sliding_choice;
}

}  // namespace twb
