// calibration: the inputs fitted to a rig's measurements, with their covariance
// (calibration.h).
#include "study/uncertainty/calibration.h"
#include "study/study_kind.h"

namespace twb {
namespace {

void add_calibration_tables(const StudyOutcome& out, std::vector<NamedTable>& tables) {
  const CalibrationOutcome& calibration = std::get<CalibrationOutcome>(out.own);
  tables.push_back({"calibration", calibration_table(calibration.fitted)});
  tables.push_back({"calibration_correlation", correlation_table(calibration.correlations)});
  tables.push_back({"calibration_points", calibration_points_table(calibration.points)});
}

}  // namespace

extern const StudyKind kCalibrationStudy{
    .run = [](BearingModel& model, StudyOutcome& out,
              const StudyRun& run) { run_calibration(model, out, run.progress, run.threads); },
    .add_tables = add_calibration_tables};

}  // namespace twb
