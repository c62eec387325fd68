// The calibration's steps 4 and 5, its tables and summary (calibration_steps.h).
#include "study/uncertainty/calibration_steps.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "results/result_cells.h"

namespace twb {

namespace {

// A value in its column's unit: a temperature in °C.
double shown(std::size_t quantity, double si) { return quantity >= 2 ? si - cells::kelvin_offset : si; }

std::string joined_quantities(const std::vector<CalibrationReading>& readings) {
  std::string out;
  for (std::size_t q = 0; q < kMeasuredQuantities; ++q)
    if (std::any_of(readings.begin(), readings.end(),
                    [q](const CalibrationReading& r) { return r.quantity == q; }))
      out += fmt::format("{}{}", out.empty() ? "" : ", ", kMeasuredQuantityColumns[q]);
  return out;
}

}  // namespace

void CalibrationSteps::tables() {
  for (std::size_t j = 0; j < n_; ++j) {
    const FittedInput& f = study_.fitted[j];
    CalibrationRow& row = calibrated_.fitted.emplace_back();
    row.parameter = f.path;
    row.parameter_unit = f.unit;
    row.start = f.start;
    row.lower = f.lower;
    row.upper = f.upper;
    row.fitted = value_[j];
    row.at_bound = at_bound_[j];
    if (covariance_ && at_bound_[j].empty()) row.sd = std::sqrt((*covariance_)(long(j), long(j)));
  }
  if (covariance_)
    for (std::size_t a : free_)
      for (std::size_t b : free_) {
        if (b < a) continue;
        CorrelationRow& c = calibrated_.correlations.emplace_back();
        c.parameter_a = study_.fitted[a].path;
        c.parameter_b = study_.fitted[b].path;
        c.covariance = (*covariance_)(long(a), long(b));
        c.correlation =
            c.covariance / std::sqrt((*covariance_)(long(a), long(a)) * (*covariance_)(long(b), long(b)));
      }
  const std::vector<PointPrediction>& fitted = cost_->last;
  for (std::size_t k = 0; k < m_; ++k) {
    const CalibrationReading& r = readings_[k];
    const MeasuredPoint& point = study_.measurements[r.point];
    CalibrationPointRow& row = calibrated_.points.emplace_back();
    row.point = long(r.point) + 1;
    row.line = point.line;
    row.load = point.load;
    row.speed = point.speed;
    row.quantity = kMeasuredQuantityColumns[r.quantity];
    row.measured = shown(r.quantity, r.measured);
    row.at_start = shown(r.quantity, at_start_[r.point].values[r.quantity]);
    row.fitted = shown(r.quantity, fitted[r.point].values[r.quantity]);
    row.sd = r.sd;
    row.residual = residuals_[k];
  }
  for (const PointPrediction& p : fitted) out_.states.push_back(p.state);
}

void CalibrationSteps::summarize() {
  out_.summary.push_back(fmt::format(
      "calibration: {} input{} fitted to {} measured value{} ({}) at {} point{}: {} after {} iterations, cost {:.6g} -> "
      "{:.6g} ({} steady solves)",
      n_, n_ == 1 ? "" : "s", m_, m_ == 1 ? "" : "s", joined_quantities(readings_), study_.measurements.size(),
      study_.measurements.size() == 1 ? "" : "s",
      summary_.termination_type == ceres::CONVERGENCE ? "converged" : "stopped",
      summary_.iterations.size() > 0 ? summary_.iterations.size() - 1 : 0, summary_.initial_cost, summary_.final_cost,
      response_->solves()));
  if (summary_.termination_type != ceres::CONVERGENCE) {
    // Said where a script looks too: run.json's outcome and Results.message (not a
    // solver failure: the inputs reached are a usable fit, only not a converged one).
    out_.summary.push_back("calibration: Ceres stopped before convergence: " + summary_.message);
    out_.message += (out_.message.empty() ? "" : "; ") +
                    std::string("the calibration stopped before converging: ") + summary_.message;
  }
  for (const CalibrationRow& row : calibrated_.fitted)
    out_.summary.push_back(fmt::format("calibration: {} = {:.6g}{} {} (start {:.6g}){}", row.parameter, row.fitted,
                                       row.sd ? fmt::format(" ± {:.2g}", *row.sd) : "", row.parameter_unit, row.start,
                                       row.at_bound.empty() ? "" : fmt::format(", at its {} bound", row.at_bound)));
  const double rms = std::sqrt(squares_ / double(std::max<std::size_t>(m_, 1)));
  out_.summary.push_back(
      relative_ ? fmt::format("calibration: root mean square residual {:.3g} of the readings (a relative fit: the "
                              "standard deviations are scaled by the residuals' own)",
                              rms)
                : fmt::format("calibration: root mean square residual {:.3g} standard deviations{}", rms,
                              m_ > nf_ ? fmt::format(" (chi-square per degree of freedom {:.3g})",
                                                     squares_ / double(m_ - nf_))
                                       : ""));
  if (relative_ && has_variance_ && !(variance_ > 0.0) && !singular_)
    out_.summary.push_back("calibration: the fit meets every reading exactly: a relative fit has no spread left to "
                           "estimate the inputs' standard deviations from");
  if (!has_variance_ && !singular_)
    out_.summary.push_back(fmt::format("calibration: {} measured values for {} free inputs leave no degree of freedom "
                                       "to estimate the residuals' variance: no standard deviations",
                                       m_, nf_));
  if (nf_ < n_)
    out_.summary.push_back(fmt::format("calibration: {} input{} held at a bound: no standard deviation, and not "
                                       "counted in the degrees of freedom (widen the bounds if the data should decide)",
                                       n_ - nf_, n_ - nf_ == 1 ? "" : "s"));
  auto combination = [&](const Eigen::VectorXd& v) {
    std::string text;
    for (std::size_t j = 0; j < n_; ++j)
      if (std::abs(v(long(j))) > 1e-3)
        text += fmt::format("{}{} by {:+.3g} x {:.3g} {}", text.empty() ? "" : " with ", study_.fitted[j].path,
                            v(long(j)), scale_[j], study_.fitted[j].unit);
    return text;
  };
  for (const Weak& w : weak_)
    out_.summary.push_back(
        !w.sd ? fmt::format("calibration: the data cannot determine the combination {} (its singular value is "
                            "{:.2g} of the largest: the readings do not move with it); fix one of these inputs or "
                            "measure what tells them apart",
                            combination(w.direction), w.ratio)
              : fmt::format("calibration: the combination {} is poorly determined: its standard deviation is {:.2g} "
                            "of the inputs' scales",
                            combination(w.direction), *w.sd));
}

}  // namespace twb
