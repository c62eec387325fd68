#include "study/calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <ceres/ceres.h>
#include <fmt/format.h>

#include "results/result_cells.h"
#include "study/measured_response.h"
#include "twb/error_family.h"
#include "twb/scene/scene_loader.h"

namespace twb {

namespace {

// Below this ratio of its smallest to largest singular value the scaled Jacobian is
// singular to the predictions' own accuracy (about 1e-8 relative: the solver's tolerance
// and the second-order differences of F_p): the data cannot tell the combination apart.
constexpr double kSingular = 1e-6;
// A combination of the scaled inputs (each by its start, or a thousandth of its range
// where that is larger) whose standard deviation exceeds a tenth of them is determined,
// but poorly.
constexpr double kPoorly = 0.1;

const char* const kColumns[] = {"torque_Nm", "f_eff", "T_mean_C", "T_max_C"};

// One measured value: its point, its quantity, the reading (SI) and its weight 1/s.
struct Reading {
  std::size_t point = 0, quantity = 0;
  double measured = 0.0, weight = 0.0;
  std::optional<double> sd;  // SI, where the scene gives it
};

// A value in its column's unit: a temperature in °C.
double shown(std::size_t quantity, double si) { return quantity >= 2 ? si - cells::kelvin_offset : si; }

// The weighted residuals of every reading, and their Jacobian in the scaled inputs x = p/scale.
class MeasurementsCost final : public ceres::CostFunction {
 public:
  MeasurementsCost(MeasuredResponse& response, const std::vector<Reading>& readings, std::vector<double> scale,
                   const std::vector<FittedInput>& fitted)
      : response_(response), readings_(readings), scale_(std::move(scale)) {
    for (const FittedInput& f : fitted) {
      lower_.push_back(f.lower);
      upper_.push_back(f.upper);
    }
    set_num_residuals(int(readings.size()));
    mutable_parameter_block_sizes()->push_back(int(scale_.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const std::size_t n = scale_.size();
    std::vector<double> p(n);
    // (clamped: the scaled bound times the scale may round a last bit past the bound)
    for (std::size_t j = 0; j < n; ++j) p[j] = std::clamp(parameters[0][j] * scale_[j], lower_[j], upper_[j]);
    const bool derivatives = jacobians && jacobians[0];
    std::vector<PointPrediction> predicted;
    std::string why;
    try {
      if (!response_.predict(p, derivatives, predicted, why)) {
        failure = why;
        return false;  // Ceres shortens the step
      }
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      failure = e.what();
      return false;
    }
    for (std::size_t k = 0; k < readings_.size(); ++k) {
      const Reading& r = readings_[k];
      const PointPrediction& at = predicted[r.point];
      residuals[k] = r.weight * (at.values[r.quantity] - r.measured);
      if (derivatives)
        for (std::size_t j = 0; j < n; ++j)
          jacobians[0][k * n + j] = r.weight * at.derivatives[r.quantity][j] * scale_[j];
    }
    last = std::move(predicted);
    return true;
  }

  mutable std::vector<PointPrediction> last;  // the last predictions that succeeded
  mutable std::string failure;               // why the last that failed did

 private:
  MeasuredResponse& response_;
  const std::vector<Reading>& readings_;
  std::vector<double> scale_, lower_, upper_;
};

class ProgressLines final : public ceres::IterationCallback {
 public:
  explicit ProgressLines(const ProgressReport& progress) : progress_(progress) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (progress_)
      progress_(fmt::format("calibration: iteration {}, cost {:.6g} ({}){}", s.iteration, s.cost,
                            s.step_is_successful ? "step taken" : "step refused",
                            s.iteration == 0 ? "" : fmt::format(", trust region {:.3g}", s.trust_region_radius)));
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const ProgressReport& progress_;
};

std::string joined_quantities(const std::vector<Reading>& readings) {
  std::string out;
  for (std::size_t q = 0; q < kMeasuredQuantities; ++q)
    if (std::any_of(readings.begin(), readings.end(), [q](const Reading& r) { return r.quantity == q; }))
      out += fmt::format("{}{}", out.empty() ? "" : ", ", kColumns[q]);
  return out;
}

}  // namespace

void run_calibration(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads) {
  const Scene& scene = model.scene();
  const Study& st = scene.study;
  const std::size_t n = st.fitted.size();

  std::vector<Reading> readings;
  // Relative where neither the scene nor the data give a deviation (the scene checked
  // that every measured quantity has one, or none does).
  const bool relative =
      std::all_of(st.measurement_sd.begin(), st.measurement_sd.end(), [](double s) { return s == 0.0; }) &&
      std::all_of(st.measurements.begin(), st.measurements.end(), [](const MeasuredPoint& p) {
        return std::all_of(p.sd.begin(), p.sd.end(), [](double s) { return std::isnan(s); });
      });
  for (std::size_t i = 0; i < st.measurements.size(); ++i)
    for (std::size_t q = 0; q < kMeasuredQuantities; ++q) {
      const double m = st.measurements[i].values[q];
      if (std::isnan(m)) continue;
      Reading& r = readings.emplace_back();
      r.point = i;
      r.quantity = q;
      r.measured = m;
      if (relative) {
        // A temperature's reading is relative to its rise above the ambient (K are not a ratio scale).
        const double ambient = st.measurements[i].ambient > 0.0 ? st.measurements[i].ambient : scene.operating.ambient;
        const double size = q >= 2 ? std::abs(m - ambient) : std::abs(m);
        if (!(size > 0.0)) {
          out.solver_failed = true;
          out.message = fmt::format("the reading of {} on line {} is {}: a relative fit cannot weigh it; give each "
                                    "quantity's standard deviation (study.sd, or a <quantity>_sd column of the data)",
                                    kColumns[q], st.measurements[i].line, q >= 2 ? "the ambient temperature" : "zero");
          return;
        }
        r.weight = 1.0 / size;
      } else {
        // The reading's own deviation where the data give it, else its quantity's.
        const double own = st.measurements[i].sd[q];
        r.sd = std::isnan(own) ? st.measurement_sd[q] : own;
        r.weight = 1.0 / *r.sd;
      }
    }
  const std::size_t m = readings.size();

  // The inputs scaled by their start (or their range, where the start is zero), so that
  // Levenberg–Marquardt's trust region and tolerances see numbers of order one.
  std::vector<double> scale(n), x(n);
  for (std::size_t j = 0; j < n; ++j) {
    const FittedInput& f = st.fitted[j];
    // (at least a thousandth of the range: a start of nearly zero would make its bounds
    // remote in the scaled input)
    scale[j] = std::max(std::abs(f.start), 1e-3 * (f.upper - f.lower));
    x[j] = f.start / scale[j];
  }
  MeasuredResponse response(load_scene_text(scene.written, scene.source, {"study={type: point}"}), st.fitted,
                            st.measurements, threads);
  auto* cost = new MeasurementsCost(response, readings, scale, st.fitted);
  ceres::Problem problem;  // owns `cost`
  problem.AddResidualBlock(cost, nullptr, x.data());
  for (std::size_t j = 0; j < n; ++j) {
    problem.SetParameterLowerBound(x.data(), int(j), st.fitted[j].lower / scale[j]);
    problem.SetParameterUpperBound(x.data(), int(j), st.fitted[j].upper / scale[j]);
  }

  // The start's predictions, for the report and a clear failure before any step.
  std::vector<double> residuals(m);
  {
    const double* block[] = {x.data()};
    if (!cost->Evaluate(block, residuals.data(), nullptr)) {
      out.solver_failed = true;
      out.message = "calibration: the start is not a state of the bearing: " + cost->failure;
      return;
    }
  }
  const std::vector<PointPrediction> at_start = cost->last;

  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = st.fit_iterations;
  // The first step within about the inputs' own size (scaled by their start), not
  // Ceres' default of 1e4 of it: a bearing far from its start may have no cool state.
  options.initial_trust_region_radius = 1.0;
  // No projected line search after each bounded step: its extra evaluations (each a
  // steady solve at every point) cost half the fit, and the bounds hold without it (the
  // step is projected onto them).
  options.max_num_line_search_step_size_iterations = 0;
  // The predictions are accurate to about 1e-8 relative (the solver's tolerance, the
  // derivatives' second-order differences): the fit is converged when a step changes
  // the cost by less than 1e-10 of itself or the scaled inputs by less than 1e-8.
  options.function_tolerance = 1e-10;
  options.parameter_tolerance = 1e-8;
  options.gradient_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;  // the points are spread over threads by the response itself
  ProgressLines lines(progress);
  options.callbacks.push_back(&lines);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) {
    out.solver_failed = true;
    out.message = fmt::format("calibration: no usable fit ({}){}", summary.message,
                              cost->failure.empty() ? "" : ": " + cost->failure);
    return;
  }

  // The fit's predictions and Jacobian.
  std::vector<double> jacobian(m * n);
  {
    const double* block[] = {x.data()};
    double* jac[] = {jacobian.data()};
    if (!cost->Evaluate(block, residuals.data(), jac)) {
      out.solver_failed = true;
      out.message = "calibration: the fit is not a state of the bearing: " + cost->failure;
      return;
    }
  }
  const std::vector<PointPrediction>& fitted = cost->last;
  // The inputs a bound holds are not free: they take no part in the covariance, nor in
  // the degrees of freedom.
  std::vector<double> value(n);
  std::vector<std::string> at_bound(n);
  std::vector<std::size_t> free;
  for (std::size_t j = 0; j < n; ++j) {
    const FittedInput& f = st.fitted[j];
    value[j] = std::clamp(x[j] * scale[j], f.lower, f.upper);
    const double tolerance = 1e-9 * (f.upper - f.lower);
    if (value[j] <= f.lower + tolerance) at_bound[j] = "lower";
    if (value[j] >= f.upper - tolerance) at_bound[j] = "upper";
    if (at_bound[j].empty()) free.push_back(j);
  }
  const std::size_t nf = free.size();
  Eigen::MatrixXd J(static_cast<long>(m), static_cast<long>(nf));
  for (std::size_t k = 0; k < m; ++k)
    for (std::size_t c = 0; c < nf; ++c) J(long(k), long(c)) = jacobian[k * n + free[c]];
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  const Eigen::VectorXd s = svd.singularValues();
  const Eigen::MatrixXd& V = svd.matrixV();
  double squares = 0.0;
  for (double r : residuals) squares += r * r;
  // The residuals' variance where the readings' own is not given (a relative fit).
  const bool has_variance = !relative || m > nf;
  const double variance = !relative ? 1.0 : m > nf ? squares / double(m - nf) : 0.0;
  const double largest = s.size() > 0 ? s(0) : 0.0;
  std::optional<Eigen::MatrixXd> covariance;  // in p, over every input (zero where held)
  // Each weak direction of the free scaled inputs (over all inputs, zero where held): its
  // singular value relative to the largest, and its standard deviation (none where
  // singular). With fewer readings than inputs the directions past the readings' count
  // have no singular value at all.
  struct Weak {
    Eigen::VectorXd direction;
    double ratio = 0.0;
    std::optional<double> sd;
  };
  std::vector<Weak> weak;
  auto over_all = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd full = Eigen::VectorXd::Zero(long(n));
    for (std::size_t c = 0; c < nf; ++c) full(long(free[c])) = v(long(c));
    return full;
  };
  for (long k = 0; k < long(nf); ++k) {
    const double ratio = k < s.size() && largest > 0.0 ? s(k) / largest : 0.0;
    if (ratio < kSingular) {
      weak.push_back({over_all(V.col(k)), ratio, std::nullopt});
    } else if (has_variance && std::sqrt(variance) / s(k) > kPoorly) {
      weak.push_back({over_all(V.col(k)), ratio, std::sqrt(variance) / s(k)});
    }
  }
  // A combination the data cannot determine leaves every free input's variance
  // unbounded along it: no covariance at all then.
  const bool singular = std::any_of(weak.begin(), weak.end(), [](const Weak& w) { return !w.sd; });
  if (!singular && has_variance && variance > 0.0 && nf > 0) {
    Eigen::MatrixXd cx = Eigen::MatrixXd::Zero(long(nf), long(nf));
    for (long k = 0; k < long(nf); ++k) cx += V.col(k) * V.col(k).transpose() / (s(k) * s(k));
    cx *= variance;
    covariance = Eigen::MatrixXd::Zero(long(n), long(n));
    for (std::size_t a = 0; a < nf; ++a)
      for (std::size_t b = 0; b < nf; ++b)
        (*covariance)(long(free[a]), long(free[b])) = cx(long(a), long(b)) * scale[free[a]] * scale[free[b]];
  }

  // The tables.
  for (std::size_t j = 0; j < n; ++j) {
    const FittedInput& f = st.fitted[j];
    CalibrationRow& row = out.calibration.emplace_back();
    row.parameter = f.path;
    row.parameter_unit = f.unit;
    row.start = f.start;
    row.lower = f.lower;
    row.upper = f.upper;
    row.fitted = value[j];
    row.at_bound = at_bound[j];
    if (covariance && at_bound[j].empty()) row.sd = std::sqrt((*covariance)(long(j), long(j)));
  }
  if (covariance)
    for (std::size_t a : free)
      for (std::size_t b : free) {
        if (b < a) continue;
        CorrelationRow& c = out.correlations.emplace_back();
        c.parameter_a = st.fitted[a].path;
        c.parameter_b = st.fitted[b].path;
        c.covariance = (*covariance)(long(a), long(b));
        c.correlation = c.covariance / std::sqrt((*covariance)(long(a), long(a)) * (*covariance)(long(b), long(b)));
      }
  for (std::size_t k = 0; k < m; ++k) {
    const Reading& r = readings[k];
    const MeasuredPoint& point = st.measurements[r.point];
    CalibrationPointRow& row = out.calibration_points.emplace_back();
    row.point = long(r.point) + 1;
    row.line = point.line;
    row.load = point.load;
    row.speed = point.speed;
    row.quantity = kColumns[r.quantity];
    row.measured = shown(r.quantity, r.measured);
    row.at_start = shown(r.quantity, at_start[r.point].values[r.quantity]);
    row.fitted = shown(r.quantity, fitted[r.point].values[r.quantity]);
    row.sd = r.sd;
    row.residual = residuals[k];
  }
  for (const PointPrediction& p : fitted) out.states.push_back(p.state);

  // What the run says.
  out.summary.push_back(fmt::format(
      "calibration: {} input{} fitted to {} measured value{} ({}) at {} point{}: {} after {} iterations, cost {:.6g} -> "
      "{:.6g} ({} steady solves)",
      n, n == 1 ? "" : "s", m, m == 1 ? "" : "s", joined_quantities(readings), st.measurements.size(),
      st.measurements.size() == 1 ? "" : "s", summary.termination_type == ceres::CONVERGENCE ? "converged" : "stopped",
      summary.iterations.size() > 0 ? summary.iterations.size() - 1 : 0, summary.initial_cost, summary.final_cost,
      response.solves()));
  if (summary.termination_type != ceres::CONVERGENCE) {
    // Said where a script looks too: run.json's outcome and Results.message (not a
    // solver failure: the inputs reached are a usable fit, only not a converged one).
    out.summary.push_back("calibration: Ceres stopped before convergence: " + summary.message);
    out.message += (out.message.empty() ? "" : "; ") +
                   std::string("the calibration stopped before converging: ") + summary.message;
  }
  for (const CalibrationRow& row : out.calibration)
    out.summary.push_back(fmt::format("calibration: {} = {:.6g}{} {} (start {:.6g}){}", row.parameter, row.fitted,
                                      row.sd ? fmt::format(" ± {:.2g}", *row.sd) : "", row.parameter_unit, row.start,
                                      row.at_bound.empty() ? "" : fmt::format(", at its {} bound", row.at_bound)));
  const double rms = std::sqrt(squares / double(std::max<std::size_t>(m, 1)));
  out.summary.push_back(
      relative ? fmt::format("calibration: root mean square residual {:.3g} of the readings (a relative fit: the "
                             "standard deviations are scaled by the residuals' own)",
                             rms)
               : fmt::format("calibration: root mean square residual {:.3g} standard deviations{}", rms,
                             m > nf ? fmt::format(" (chi-square per degree of freedom {:.3g})", squares / double(m - nf))
                                   : ""));
  if (relative && has_variance && !(variance > 0.0) && !singular)
    out.summary.push_back("calibration: the fit meets every reading exactly: a relative fit has no spread left to "
                          "estimate the inputs' standard deviations from");
  if (!has_variance && !singular)
    out.summary.push_back(fmt::format("calibration: {} measured values for {} free inputs leave no degree of freedom to "
                                      "estimate the residuals' variance: no standard deviations",
                                      m, nf));
  if (nf < n)
    out.summary.push_back(fmt::format("calibration: {} input{} held at a bound: no standard deviation, and not counted "
                                      "in the degrees of freedom (widen the bounds if the data should decide)",
                                      n - nf, n - nf == 1 ? "" : "s"));
  auto combination = [&](const Eigen::VectorXd& v) {
    std::string text;
    for (std::size_t j = 0; j < n; ++j)
      if (std::abs(v(long(j))) > 1e-3)
        text += fmt::format("{}{} by {:+.3g} x {:.3g} {}", text.empty() ? "" : " with ", st.fitted[j].path, v(long(j)),
                            scale[j], st.fitted[j].unit);
    return text;
  };
  for (const Weak& w : weak)
    out.summary.push_back(
        !w.sd ? fmt::format("calibration: the data cannot determine the combination {} (its singular value is "
                            "{:.2g} of the largest: the readings do not move with it); fix one of these inputs or "
                            "measure what tells them apart",
                            combination(w.direction), w.ratio)
              : fmt::format("calibration: the combination {} is poorly determined: its standard deviation is {:.2g} "
                            "of the inputs' scales",
                            combination(w.direction), *w.sd));
}

}  // namespace twb
