// Study type distress_curve (issue: the fold curve in a second parameter): W_d found and
// proven at one end of the parameter range, then the fold itself continued in the
// parameter (solver/fold_curve.h) across the range, with the state at the fold all
// along it; where the fold curve turns back at a cusp, sudden distress ends (below it the
// bearing heats gradually), and the curve goes on as the hot branch's turning point.
#pragma once

#include <optional>
#include <string>

#include "model/bearing_model.h"
#include "study/study_runner.h"

namespace twb {

// One curve, on `model` (the scene's bearing, or one member of the study's family);
// `member` (the family parameter's value, if any) tags its rows. Rows and summary lines
// are appended to `out` (the rows to its DistressCurveOutcome, made where there is none).
// Its independent pieces (the two ends' searches, the fold's error bars, each limit
// curve) run on up to `threads` threads, each on models of its own: the results are the
// same for any count.
void run_fold_curve(BearingModel& model, std::optional<double> member, const std::string& label, StudyOutcome& out,
                    const ProgressReport& progress, int threads = 1);

// The column of fold_curve.csv that holds the curve's parameter.
std::string fold_curve_column(CurveParameter p);

}  // namespace twb
