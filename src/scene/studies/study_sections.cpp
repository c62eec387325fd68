// The study types as the scene file sees them, each registered here by its section
// (scene/studies/<type>_keys.cpp).
#include "scene/studies/study_section.h"

#include "twb/error_family.h"

namespace twb::scene_io {

extern const StudySection kPointKeys, kLoadSweepKeys, kDistressMapKeys, kTransientKeys, kSlidingChoiceKeys,
    kDistressCurveKeys, kSensitivityKeys, kReliabilityKeys, kCalibrationKeys, kDutyCycleKeys, kLifeKeys;

const StudySection& study_section(StudyType type) {
  switch (type) {
    case StudyType::point: return kPointKeys;
    case StudyType::load_sweep: return kLoadSweepKeys;
    case StudyType::distress_map: return kDistressMapKeys;
    case StudyType::transient: return kTransientKeys;
    case StudyType::sliding_choice: return kSlidingChoiceKeys;
    case StudyType::distress_curve: return kDistressCurveKeys;
    case StudyType::sensitivity: return kSensitivityKeys;
    case StudyType::reliability: return kReliabilityKeys;
    case StudyType::calibration: return kCalibrationKeys;
    case StudyType::duty_cycle: return kDutyCycleKeys;
    case StudyType::life: return kLifeKeys;
  }
  throw InternalError("a study type without its scene section");
}

}  // namespace twb::scene_io
