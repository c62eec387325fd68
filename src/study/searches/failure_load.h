// Where the bearing fails (docs/physics.md section 8, "Failure load"): the first of
// thermo-viscous distress (the fold, located and proven by the distress search) and the
// first load where the branch continued from the start crosses a failure criterion (the
// oil's maximum temperature, its flash point, a material's temperature limit, the least
// film ratio). Each crossing is the root of the criterion's margin along the branch,
// bracketed by two of its states and located by TOMS 748 on the load, each trial state
// continued from the nearest state below it; the root is located to the search's
// bracket width, and reported where the margin's secant through the final bracket
// vanishes.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <utility>

#include "study/searches/fold_proof.h"
#include "model/bearing_model.h"
#include "model/limit_thresholds.h"
#include "solver/kinsol_newton.h"
#include "twb/results/distress_table.h"

namespace twb {

struct FailureSettings {
  double load_start = 0.0, load_end = 0.0;  // N: the searched range
  double bracket_width = 0.002;             // relative: how closely a crossing is located
};

// How far state u of `model` is from crossing criterion `kind` (limit_thresholds.h:
// failure_margin); none where the limits do not apply it.
std::optional<double> state_margin(const BearingModel& model, std::span<const double> u, LimitKind kind,
                                   const OperatingLimits& limits);

// Fills row.criterion_loads, failure_load, criterion and failure from the branch's states
// (load, state) in rising load, its end at the fold included where there is one, and
// row.distress_load. Steady solves it made are counted in `solves`. The model comes back
// at the load it was given (a ParameterScope).
// crossings, if given, receives each criterion's crossing (load, state), empty where none.
void locate_failure(BearingModel& model, const BranchStates& branch, const FailureSettings& settings,
                    DistressRow& row, long& solves, BranchStates* crossings = nullptr);

// The crossing of `kind` near `state` (a state of the cool branch at its load, e.g. the
// crossing at a nearby parameter value, predicted): the secant on the margin in load
// from there (the first step with `slope`, dmargin/dW, where negative), each state by
// Newton from the last moved along the branch's tangent (a step Newton cannot take
// halved, twice at most, and the branch continued to the last halving where Newton
// still fails), until the next step
// would be a tenth of `width`: the state in hand is then the crossing's to that, the
// secant converging superlinearly. On success
// `state` becomes the crossing's (load, state), `slope` the last secant's and
// `described`, if given, its description; none, with `why`, where the crossing lies
// above load_end or the branch cannot be continued to it (it folds first). `corrector`,
// if given, is a Newton solver of `model` (one per curve: its analysis is reused).
// load_only: the caller needs the crossing's load alone (a refined mesh's, for an error
// bar): each Newton solve stops where the margin is settled to what moves the root by
// a fiftieth of `width`; the load returned is the secant's last root (closer than the
// last state solved), and the state returned is that last solve's, neither at that load
// nor converged to the solver's tolerance. The caller has just solved `state` with
// `corrector` (its factors are the start's), and a negative `slope` is the branch's
// own there: its Newton step, when short enough, is the root.
std::optional<double> crossing_near(BearingModel& model, LimitKind kind, std::pair<double, std::vector<double>>& state,
                                    double& slope, double width, double load_end, long& solves, std::string& why,
                                    KinsolNewton* corrector = nullptr, BearingState* described = nullptr,
                                    bool load_only = false);

// "fails at 307.6 N by the oil's peak temperature (no thermo-viscous distress up to 4000 N)":
// the sentence of a row whose failure fields are set.
std::string failure_sentence(const DistressRow& row, double load_end);
// The same with the mesh-converged W_fail first, where the row has it: "fails at 202.8 ±
// 1.5 N by thermo-viscous distress (mesh-converged on 9x66 17x132 33x264, observed order
// 1.78; 188.38 N on the scene's mesh)".
std::string converged_failure_sentence(const DistressRow& row, double load_end);

}  // namespace twb
