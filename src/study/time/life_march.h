// A washer's life (study type life, docs/physics.md section 20): the worn depths
// integrated in the wear's slow time by IDA at the operating point, everything else of
// the bearing quasi-steady ([W4]), the washer reported every `report_every`, until the
// duration, the wear allowance (located between two steps) or distress (the steady
// bearing lost as the faces wear: IDA cannot go on).
#pragma once

#include <string>

#include "model/bearing_model.h"
#include "model/wear_effect.h"
#include "study/searches/distress_search.h"
#include "twb/study/study_outcome.h"

namespace twb {

// At one operating point, or through the scene's repeated duty cycle (cycle_life.h).
void run_life(BearingModel& model, StudyOutcome& out, const ProgressReport& progress);

// The failure search along a life at the operating load: from a quarter of it up to twenty
// times it, not marched past distress (a worn washer's refined meshes would not have its
// depths: the failure load is the scene's mesh's, without an error bar).
DistressSearchSettings life_failure_search(double operating_load);

// A face's wear as life.csv reports it.
inline FaceWear face_wear(const WearEffect::Worn& w) { return {w.deepest, w.mean, w.volume, w.rq}; }

// The life's message and summary from its rows: `subject` ("life at 150 N"), how it
// ended, each face's wear at the end, the failure load new and at the end.
void summarize_life(StudyOutcome& out, const std::string& subject, const std::string& ending);

}  // namespace twb
