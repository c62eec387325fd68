// The load range and grid a study's distress searches cover (load_sweep, distress_map,
// sliding_choice), and how a search's failure joins the study's message.
#pragma once

#include <vector>

#include "study/searches/distress_search.h"
#include "twb/study/study_outcome.h"

namespace twb {

// The requested grid: load_steps loads from the range's start to its end, ends included.
std::vector<double> load_grid(const LoadGrid& grid);
// The error bars the study asks for (load_sweep, distress_map): the failure loads', and
// with every_state every state's.
void ask_error_bars(const ErrorBarSettings& bars, DistressSearchSettings& settings);
// A sweep's search: the range, the requested grid, and on past distress.
DistressSearchSettings grid_settings(const LoadGrid& grid);
// A search that failed or has something to say adds it to the study's message.
void keep_failure(StudyOutcome& out, const DistressSearch& found);

}  // namespace twb
