// The error bars of a distress search's answers (study.error_estimate): W_d's and every
// failure criterion's crossing again on the refined mesh and extrapolated (richardson),
// or every state of the search again on it (every_state).
#pragma once

#include "model/bearing_model.h"
#include "study/searches/distress_search.h"
#include "study/parallel/parallel.h"

namespace twb {

// Every state of a search again on the refined mesh (study.error_estimate: every_state),
// on the search's thread; a state without one says why in the search's row.
void estimate_state_errors(const BearingModel& model, DistressSearch& found, const ProgressReport& progress);
class SpareThreads;

// The bars of a search's failure loads (study.error_estimate: richardson): W_d's fold and
// each failure criterion's crossing again on the refined mesh and extrapolated, each an
// independent piece on its own refined model, run on the calling thread and on those
// `spare` lends (none: one after the other; the results are the same); then W_fail's
// mesh-converged value and error bar: W_d's where distress sets it, else its
// criterion's. Returns the KLU factorizations made on lent threads (the calling
// thread's own counts hold the rest).
long estimate_failure_errors(const BearingModel& model, const DistressSearchSettings& settings,
                             DistressSearch& found, const ProgressReport& progress, SpareThreads* spare);

}  // namespace twb
