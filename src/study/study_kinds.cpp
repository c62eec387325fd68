// The study types, each registered here by its descriptor (study/types/<type>_study.cpp).
#include "study/study_kind.h"

#include "twb/error_family.h"

namespace twb {

extern const StudyKind kPointStudy, kLoadSweepStudy, kDistressMapStudy, kTransientStudy, kSlidingChoiceStudy,
    kDistressCurveStudy, kSensitivityStudy, kReliabilityStudy, kCalibrationStudy, kDutyCycleStudy, kLifeStudy;

const StudyKind& study_kind(StudyType type) {
  switch (type) {
    case StudyType::point: return kPointStudy;
    case StudyType::load_sweep: return kLoadSweepStudy;
    case StudyType::distress_map: return kDistressMapStudy;
    case StudyType::transient: return kTransientStudy;
    case StudyType::sliding_choice: return kSlidingChoiceStudy;
    case StudyType::distress_curve: return kDistressCurveStudy;
    case StudyType::sensitivity: return kSensitivityStudy;
    case StudyType::reliability: return kReliabilityStudy;
    case StudyType::calibration: return kCalibrationStudy;
    case StudyType::duty_cycle: return kDutyCycleStudy;
    case StudyType::life: return kLifeStudy;
  }
  throw InternalError("a study type without a descriptor");
}

void add_distress_table(const StudyOutcome& out, std::vector<NamedTable>& tables) {
  tables.push_back({"distress", distress_table(out.distress, out.parameter_columns, out.sliding_column)});
}

void add_distress_table_if_any(const StudyOutcome& out, std::vector<NamedTable>& tables) {
  if (!out.distress.empty()) add_distress_table(out, tables);
}

}  // namespace twb
