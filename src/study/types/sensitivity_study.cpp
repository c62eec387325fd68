// sensitivity: the derivatives of the state's quantities, and of the failure load where a
// load range is given, against the scene's inputs (sensitivity.h).
#include "study/uncertainty/sensitivity.h"
#include "study/study_kind.h"

namespace twb {
namespace {

void add_sensitivity_tables(const StudyOutcome& out, std::vector<NamedTable>& tables) {
  add_distress_table_if_any(out, tables);
  tables.push_back({"sensitivity", sensitivity_table(std::get<SensitivityOutcome>(out.own).rows)});
}

}  // namespace

extern const StudyKind kSensitivityStudy{
    .run = [](BearingModel& model, StudyOutcome& out,
              const StudyRun& run) { run_sensitivity(model, out, run.progress, run.threads); },
    .add_tables = add_sensitivity_tables};

}  // namespace twb
