// Where a duty cycle's march starts (docs/physics.md section 19): the steady state at the
// schedule's first point, or the state an earlier cycle ended in (--continue-from); and,
// for a washer that starts turning from rest under load, the film as it starts to turn.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "solver/kinsol_newton.h"
#include "study/time/operating_schedule.h"
#include "twb/results/cycle_state.h"
#include "twb/study/study_outcome.h"

namespace twb {

// The state the march starts from at the schedule's first point, the model set to that
// point's inputs; its row is added to out.states (states.csv: the start). `start`: an
// earlier cycle's end to go on from (std::invalid_argument where it is another bearing's,
// `bearing` this one's, or ends elsewhere than this schedule starts). Empty, with
// out.solver_failed and out.message, where no steady state is found there.
//
// At rest under load (speed 0, load > 0) the steady state has no film pressure at all:
// every cavitation row sits at its kink (p = 0 and its flow balance 0), and nothing ties
// the squeeze's rates to the washer, so the march's first Newton iterations find no
// consistent state as the washer starts to turn. The march starts instead from the
// limit of the turning film's quasi-steady states as the speed falls to zero: the steady
// state a millionth of the first segment on (its speed a millionth of the segment's
// change), whose pressures carry a film that turns. Its temperatures differ from the
// rest's by the heat of a millionth of the speed (5e-5 K on the paper's washer at 100 N):
// nothing a cycle can see. The row in states.csv stays the state at rest.
std::optional<std::vector<double>> cycle_start(BearingModel& model, const OperatingSchedule& schedule,
                                               const NewtonSettings& newton, const CycleState* start,
                                               const std::string& bearing, StudyOutcome& out,
                                               const ProgressReport& progress);

}  // namespace twb
