#include "study/types/searched_loads.h"

namespace twb {

std::vector<double> load_grid(const Study& st) {
  std::vector<double> grid;
  for (int k = 0; k < st.load_steps; ++k)
    grid.push_back(st.load_start + (st.load_end - st.load_start) * k / (st.load_steps - 1));
  return grid;
}

DistressSearchSettings range_settings(const Study& st) {
  DistressSearchSettings s;
  s.load_start = st.load_start;
  s.load_end = st.load_end;
  s.bracket_width = st.bracket_width;
  s.keep_state_vectors = st.error_estimate == ErrorEstimate::every_state;
  return s;
}

void ask_failure_error_bars(const Study& st, DistressSearchSettings& s) {
  s.failure_error_bars = st.error_estimate != ErrorEstimate::none;
  s.error_tolerance = st.tolerance;
}

DistressSearchSettings grid_settings(const Study& st) {
  DistressSearchSettings s = range_settings(st);
  s.grid = load_grid(st);
  s.continue_past_distress = true;
  return s;
}

void keep_failure(StudyOutcome& out, const DistressSearch& found) {
  if (!found.failed && found.message.empty()) return;
  out.solver_failed = out.solver_failed || found.failed;
  out.message += (out.message.empty() ? "" : "; ") + found.message;
}

}  // namespace twb
