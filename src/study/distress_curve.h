// Study type distress_curve (issue: the fold curve in a second parameter): W_d found and
// proven at one end of the parameter range, then the fold itself continued in the
// parameter (solver/fold_curve.h) across the range, with the state at the fold all
// along it; where the fold curve turns back at a cusp, sudden distress ends (below it the
// bearing heats gradually), and the curve goes on as the hot branch's turning point.
#pragma once

#include "twb/model/bearing_model.h"
#include "twb/study/study_runner.h"

namespace twb {

void run_distress_curve(BearingModel& model, StudyOutcome& out, const ProgressReport& progress);

}  // namespace twb
