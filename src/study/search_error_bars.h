// The error bars of a distress search's answers (study.error_estimate): W_d's and every
// failure criterion's crossing again on the refined mesh and extrapolated (richardson),
// or every state of the search again on it (every_state).
#pragma once

#include "model/bearing_model.h"
#include "study/distress_search.h"
#include "study/parallel.h"

namespace twb {

// Every state of a search again on the refined mesh (study.error_estimate: every_state),
// on the search's thread; a state without one says why in the search's row.
void estimate_state_errors(const BearingModel& model, DistressSearch& found, const ProgressReport& progress);
// W_d's error bar (study.error_estimate: richardson) for a search that found a fold.
void estimate_mesh_error(const BearingModel& model, const DistressSearchSettings& settings, DistressSearch& found,
                         const ProgressReport& progress);
// Each failure criterion's crossing again on the refined mesh (study.error_estimate:
// richardson), and W_fail's mesh-converged value and error bar: W_d's where distress
// sets it, else its criterion's.
void estimate_crossing_errors(const BearingModel& model, const DistressSearchSettings& settings, DistressSearch& found,
                              const ProgressReport& progress);

}  // namespace twb
