// distress_map: the failure loads over speeds and map combinations, each searched on its
// own or followed from its neighbour's (followed_map.h).
#include "study/searches/followed_map.h"
#include "study/searches/study_searches.h"
#include "study/study_kind.h"
#include "study/types/searched_loads.h"

namespace twb {
namespace {

void run_distress_map(BearingModel& base, StudyOutcome& out, const StudyRun& run) {
  const DistressMapSettings& map = std::get<DistressMapSettings>(base.scene().study.settings);
  DistressSearchSettings settings = range_settings(map.search);
  settings.march_past_distress = false;  // the map keeps neither the hot states nor the trajectories
  settings.search_past_failure = map.search_past_failure;
  ask_error_bars(map.error_bars, settings);
  if (map.map_method == MapMethod::follow) {
    run_followed_map(base, settings, out, run.progress, run.how);
    return;
  }
  const std::vector<Variant> variants = parameter_variants(base.scene(), out.parameter_columns);
  run_searches(base, variants, settings, run.progress, run.how, out.timings, out.diagnostics,
               [&](const Variant&, std::size_t, const BearingModel&, DistressSearch& found) {
    out.distress.push_back(found.row);
    // The cool branch's states are results too (f_eff, temperature against load).
    out.states.insert(out.states.end(), found.states.begin(),
                      found.states.begin() + std::ptrdiff_t(found.cool_states));
    // One point that fails must not lose the map's other rows.
    if (found.failed) out.message += (out.message.empty() ? "" : "; ") + found.message;
  });
}

// A followed map is one piece of work: each combination starts from its neighbour's.
bool searched_apart(const Study& study) {
  return std::get<DistressMapSettings>(study.settings).map_method == MapMethod::search;
}

}  // namespace

// (a followed map counts its threads' work in run_followed_map)
extern const StudyKind kDistressMapStudy{.run = run_distress_map,
                                         .add_tables = add_distress_table,
                                         .searches_count_their_work = true,
                                         .independent_searches = searched_apart};

}  // namespace twb
