#include "study/uncertainty/calibration.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "study/uncertainty/calibration_steps.h"
#include "twb/error_family.h"

namespace twb {

void run_calibration(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads) {
  CalibrationSteps(model, out, progress, threads).run();
}

CalibrationSteps::CalibrationSteps(const BearingModel& model, StudyOutcome& out, const ProgressReport& progress,
                                   int threads)
    : scene_(model.scene()),
      study_(std::get<CalibrationSettings>(scene_.study.settings)),
      n_(study_.fitted.size()),
      out_(out),
      calibrated_(out.own_part<CalibrationOutcome>()),
      progress_(progress),
      threads_(threads) {}

void CalibrationSteps::run() {
  if (ran_) throw InternalError("calibration: the steps are run once only");
  ran_ = true;
  if (!weigh_readings() || !fit()) return;
  spread();
  tables();
  summarize();
}

bool CalibrationSteps::weigh_readings() {
  // Relative where neither the scene nor the data give a deviation (the scene checked
  // that every measured quantity has one, or none does).
  relative_ =
      std::all_of(study_.measurement_sd.begin(), study_.measurement_sd.end(), [](double s) { return s == 0.0; }) &&
      std::all_of(study_.measurements.begin(), study_.measurements.end(), [](const MeasuredPoint& p) {
        return std::all_of(p.sd.begin(), p.sd.end(), [](double s) { return std::isnan(s); });
      });
  for (std::size_t i = 0; i < study_.measurements.size(); ++i)
    for (std::size_t q = 0; q < kMeasuredQuantities; ++q) {
      const double m = study_.measurements[i].values[q];
      if (std::isnan(m)) continue;
      CalibrationReading& r = readings_.emplace_back();
      r.point = i;
      r.quantity = q;
      r.measured = m;
      if (relative_) {
        // A temperature's reading is relative to its rise above the ambient (K are not a ratio scale).
        const double ambient =
            study_.measurements[i].ambient > 0.0 ? study_.measurements[i].ambient : scene_.operating.ambient;
        const double size = q >= 2 ? std::abs(m - ambient) : std::abs(m);
        if (!(size > 0.0)) {
          out_.solver_failed = true;
          out_.message = fmt::format("the reading of {} on line {} is {}: a relative fit cannot weigh it; give each "
                                     "quantity's standard deviation (study.sd, or a <quantity>_sd column of the data)",
                                     kMeasuredQuantityColumns[q], study_.measurements[i].line,
                                     q >= 2 ? "the ambient temperature" : "zero");
          return false;
        }
        r.weight = 1.0 / size;
      } else {
        // The reading's own deviation where the data give it, else its quantity's.
        const double own = study_.measurements[i].sd[q];
        r.sd = std::isnan(own) ? study_.measurement_sd[q] : own;
        r.weight = 1.0 / *r.sd;
      }
    }
  m_ = readings_.size();
  return true;
}

}  // namespace twb
