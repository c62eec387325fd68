// load_sweep: one distress search per speed and map combination over the requested load
// grid, each continued past distress (the hot states and the runaway's first step).
#include "study/searches/study_searches.h"
#include "study/study_kind.h"
#include "study/types/searched_loads.h"

namespace twb {
namespace {

void run_load_sweep(BearingModel& model, StudyOutcome& out, const StudyRun& run) {
  const std::vector<Variant> variants = parameter_variants(model.scene(), out.parameter_columns);
  const LoadSweepSettings& sweep = std::get<LoadSweepSettings>(model.scene().study.settings);
  DistressSearchSettings settings = grid_settings(sweep.grid);
  ask_error_bars(sweep.error_bars, settings);
  run_searches(model, variants, settings, run.progress, run.how, out.timings, out.diagnostics,
               [&](const Variant&, std::size_t, const BearingModel&, DistressSearch& found) {
                 out.states.insert(out.states.end(), found.states.begin(), found.states.end());
                 out.trajectory.insert(out.trajectory.end(), found.runaway.begin(), found.runaway.end());
                 out.distress.push_back(found.row);
                 keep_failure(out, found);
               });
}

}  // namespace

extern const StudyKind kLoadSweepStudy{.run = run_load_sweep,
                                       .add_tables = add_distress_table,
                                       .searches_count_their_work = true,
                                       .independent_searches = for_all_settings};

}  // namespace twb
