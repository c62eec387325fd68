// The limit curves of a distress curve (docs/physics.md section 8): every failure
// criterion crossed at an end of the parameter's range continued across it, each on a
// model of its own (limit_curve.h), and their rows and summary lines.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "study/accuracy/fold_curve_bars.h"
#include "study/searches/limit_curve.h"
#include "twb/study/study_outcome.h"

namespace twb {

// Each criterion's crossing (load, state) on a searched branch, kFailureCriteria order.
using Crossings = std::vector<std::pair<double, std::vector<double>>>;

// The curve parameter's value as a user reads it (a distress curve's study): a speed in
// rpm where the scene gave the curve's range so.
std::string shown_parameter(const Study& st, double v);

// One criterion's limit curve (limit_curve.h), from the first end searched that crosses
// it to the other end, on a model of its own.
struct LimitCurveJob {
  LimitKind kind = LimitKind::oil_temperature;
  double from = 0.0, to = 0.0;
  std::pair<double, std::vector<double>> start;
  LimitCurve curve;
  // Each point's error bar (LimitCurveSettings::error_bars), or why it has none.
  std::vector<FoldBar> bars;
  double seconds = 0.0;
};

// The jobs for the crossings found at the range's ends (parameter value, crossings).
std::vector<LimitCurveJob> limit_curve_jobs(const DistressCurveSettings& curve,
                                            const std::vector<std::pair<double, Crossings>>& ends);
// W_d along this curve's distress fold (the member's rows so far, sorted in the
// parameter), interpolated linearly between its points; none outside the fold's range.
std::function<std::optional<double>(double)> distress_fold_of(const std::vector<FoldCurveRow>& rows,
                                                              std::optional<double> member);
// Traces a job's curve on a model of the scene, then with settings.error_bars each point's
// bar; a failure ends the curve with its reason.
void trace_job(const Scene& scene, CurveParameter which, const LimitCurveSettings& settings, LimitCurveJob& job);
// A traced limit curve's rows in fold_curve.csv (the criterion's name in the fold
// column) and its summary line.
void add_limit_curve(const LimitCurveJob& job, const Study& st, std::optional<double> member,
                     const std::string& label, double tolerance, StudyOutcome& out,
                     const std::function<void(const std::string&)>& say);

}  // namespace twb
