#include "study/types/searched_loads.h"

namespace twb {

std::vector<double> load_grid(const LoadGrid& grid) {
  std::vector<double> loads;
  const LoadRange& range = grid.loads;
  for (int k = 0; k < grid.load_steps; ++k)
    loads.push_back(range.start + (range.end - range.start) * k / (grid.load_steps - 1));
  return loads;
}

void ask_error_bars(const ErrorBarSettings& bars, DistressSearchSettings& s) {
  s.keep_state_vectors = bars.estimate == ErrorEstimate::every_state;
  s.failure_error_bars = bars.estimate != ErrorEstimate::none;
  s.error_tolerance = bars.tolerance;
}

DistressSearchSettings grid_settings(const LoadGrid& grid) {
  DistressSearchSettings s = range_settings(grid);
  s.grid = load_grid(grid);
  s.continue_past_distress = true;
  return s;
}

void keep_failure(StudyOutcome& out, const DistressSearch& found) {
  if (!found.failed && found.message.empty()) return;
  out.solver_failed = out.solver_failed || found.failed;
  out.message += (out.message.empty() ? "" : "; ") + found.message;
}

}  // namespace twb
