// The scene's operating point solved from the cold start, and a state as the studies
// record it with its solver's report (a point study, a sensitivity study, a transient's
// end).
#pragma once

#include <span>
#include <vector>

#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"
#include "twb/study/study_outcome.h"

namespace twb {

// The state u solved by `rep`, as states.csv records it.
SolvedState recorded_state(const BearingModel& model, std::span<const double> u, const SteadyReport& rep);

// The operating point from the cold start, recorded in out.states (its Newton work in
// out.timings); false, with out.solver_failed and the reason, where it has no steady state.
bool solve_operating_point(BearingModel& model, StudyOutcome& out, std::vector<double>& u);

}  // namespace twb
