// duty_cycle: the bearing marched in real time through an operating schedule
// (duty_cycle.h), from the steady state at its start or from an earlier cycle's end.
#include "study/time/duty_cycle.h"
#include "study/study_kind.h"

namespace twb {
namespace {

void add_cycle_tables(const StudyOutcome& out, std::vector<NamedTable>& tables) {
  add_distress_table_if_any(out, tables);
  tables.push_back({"trajectory", trajectory_table(out.trajectory, {}, false, true)});
  tables.push_back({"cycle_events", cycle_events_table(std::get<DutyCycleOutcome>(out.own).events)});
}

}  // namespace

extern const StudyKind kDutyCycleStudy{
    .run = [](BearingModel& model, StudyOutcome& out,
              const StudyRun& run) { run_duty_cycle(model, out, run.progress, run.cycle_start); },
    .add_tables = add_cycle_tables,
    .continues_from = true};

}  // namespace twb
