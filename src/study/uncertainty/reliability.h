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

class SearchScheduler;

// The Monte Carlo samples run on `threads` threads here, or through `scheduler` (the
// ranks of an MPI job: every rank runs the study, FORM included, and judges its share of
// each batch; the batch's verdicts and states are then shared, so that every rank holds
// the same states and draws the same next batch). Only the process that takes the
// results goes on past the Monte Carlo check.
void run_reliability(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads,
                     SearchScheduler* scheduler = nullptr);

}  // namespace twb
