// sliding_choice: which film slides (docs/physics.md section 2). Both configurations are
// swept over the load grid at every speed, each continued past its own distress; at every
// grid load the one of lower friction torque is chosen, the paper's assumption that the
// washer settles where the friction loss is least.
#include <algorithm>
#include <cmath>

#include "study/searches/study_searches.h"
#include "study/study_kind.h"
#include "study/types/searched_loads.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

void run_sliding_choice(BearingModel& base, StudyOutcome& out, const StudyRun& run) {
  const LoadGrid& requested = std::get<SlidingChoiceSettings>(base.scene().study.settings).grid;
  SlidingChoiceOutcome& choice = out.own_part<SlidingChoiceOutcome>();
  out.sliding_column = true;
  std::vector<Variant> variants;
  for (SlidingFilm film : {SlidingFilm::carrier_washer, SlidingFilm::washer_gear}) {
    Scene scene = base.scene();
    scene.operating.sliding = film;
    const std::string name(scene_name(film));
    variants.push_back({std::move(scene), {}, film, ", sliding " + name});
  }
  const std::vector<double> grid = load_grid(requested);
  // Per speed and grid load, the state of each configuration that reached it.
  std::vector<std::vector<std::vector<SlidingRow>>> at(study_speeds(base).size(),
                                                        std::vector<std::vector<SlidingRow>>(grid.size()));
  run_searches(base, variants, grid_settings(requested), run.progress, run.how, out.timings, out.diagnostics,
               [&](const Variant&, std::size_t speed, const BearingModel& model, DistressSearch& found) {
    const auto film = std::find_if(model.films().begin(), model.films().end(), [](const Film& f) { return f.sliding; });
    const double area = film->mesh.area();
    for (const SolvedState& state : found.states)
      for (std::size_t k = 0; k < grid.size(); ++k)
        if (std::abs(state.state.load - grid[k]) <= 1e-9 * grid[k]) at[speed][k].push_back({state, area, false});
    out.trajectory.insert(out.trajectory.end(), found.runaway.begin(), found.runaway.end());
    out.distress.push_back(found.row);
    keep_failure(out, found);
  });
  for (auto& speed : at)
    for (std::vector<SlidingRow>& rows : speed) {
      if (rows.empty()) continue;
      auto best = std::min_element(rows.begin(), rows.end(), [](const SlidingRow& a, const SlidingRow& b) {
        return a.solved.state.torque < b.solved.state.torque;
      });
      best->chosen = true;
      out.states.push_back(best->solved);
      choice.rows.insert(choice.rows.end(), rows.begin(), rows.end());
    }
}

void add_sliding_tables(const StudyOutcome& out, std::vector<NamedTable>& tables) {
  add_distress_table(out, tables);
  tables.push_back({"sliding", sliding_table(std::get<SlidingChoiceOutcome>(out.own).rows)});
}

}  // namespace

extern const StudyKind kSlidingChoiceStudy{.run = run_sliding_choice,
                                           .add_tables = add_sliding_tables,
                                           .searches_count_their_work = true,
                                           .independent_searches = for_all_settings};

}  // namespace twb
