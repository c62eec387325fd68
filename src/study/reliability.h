// The probability that the bearing fails (study type reliability, docs/physics.md
// section 17): uncertain inputs with their distributions, the failure load W_fail(x) at
// the inputs (failure_at_inputs.h), and the operating load W of the scene: P_f =
// P(W_fail(X) ≤ W) by FORM with W_fail's exact gradients (first_order_reliability.h),
// checked by importance sampling round the design point (importance_sampling.h), and
// the loads whose failure probabilities are the ones asked for (inverse FORM).
#pragma once

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"

namespace twb {

void run_reliability(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads);

}  // namespace twb
