// A distress map whose combinations' failure loads are followed by Newton from their
// neighbours' (study.method: follow, docs/physics.md section 16).
#pragma once

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"
#include "study/searches/study_searches.h"

namespace twb {

// Every combination of the map's axes and speeds: a failure search at the first, then
// each criterion settled there (the fold on the minimally augmented system, each limit's
// crossing on its margin's root) followed along the axes in chains, the first axis
// first: along axis 0 from the first combination, then along axis 1 from each point of
// that chain, and so on, the speeds last. A point whose move fails, or at which a
// criterion not followed is crossed first, is searched. Each point starts from one fixed
// neighbour, so the rows do not depend on the thread count. Rows in the search's order
// (combination outer, speed inner); no states, trajectories or error bars.
// `settings`: the map's search, as a searched map's.
void run_followed_map(BearingModel& base, const DistressSearchSettings& settings, StudyOutcome& out,
                      const ProgressReport& progress, const Running& how);

}  // namespace twb
