// reliability: the probability of failure at the operating load over the uncertain
// inputs, and the loads of the wanted probabilities (reliability.h).
#include "study/uncertainty/reliability.h"
#include "study/study_kind.h"

namespace twb {
namespace {

void add_reliability_tables(const StudyOutcome& out, std::vector<NamedTable>& tables) {
  add_distress_table_if_any(out, tables);
  const ReliabilityOutcome& reliability = std::get<ReliabilityOutcome>(out.own);
  tables.push_back({"reliability", reliability_table(reliability.rows)});
  tables.push_back({"design_point", design_point_table(reliability.design_points)});
}

// Its Monte Carlo batches spread over the ranks of an MPI job (each batch shares what it
// found with the next, which the slices of a job array cannot).
bool samples_spread(const Study& study) { return std::get<ReliabilitySettings>(study.settings).max_samples > 0; }

}  // namespace

extern const StudyKind kReliabilityStudy{
    .run = [](BearingModel& model, StudyOutcome& out,
              const StudyRun& run) { run_reliability(model, out, run.progress, run.threads, run.how.scheduler); },
    .add_tables = add_reliability_tables,
    .spreads_over_ranks = samples_spread};

}  // namespace twb
