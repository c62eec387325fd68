// life: the washer worn at its operating point over its life in the wear's slow time
// (life_march.h).
#include "study/study_kind.h"
#include "study/time/life_march.h"

namespace twb {

extern const StudyKind kLifeStudy{
    .run = [](BearingModel& model, StudyOutcome& out, const StudyRun& run) { run_life(model, out, run.progress); },
    .add_tables = [](const StudyOutcome& out, std::vector<NamedTable>& tables) {
      add_distress_table_if_any(out, tables);  // the failure searches along the life
      tables.push_back({"life", life_table(std::get<LifeOutcome>(out.own).rows)});
      tables.push_back({"worn_profile", worn_profile_table(std::get<LifeOutcome>(out.own).worn)});
    }};

}  // namespace twb
