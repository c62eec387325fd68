// The calibration (calibration.h) as its steps, with the fit's state in one place:
//   1. weigh the readings  each measured value with its weight: 1/s, or in a relative
//                          fit 1/|m| (calibration.cpp)
//   2. fit                 Ceres' bounded Levenberg–Marquardt from the start, in the
//                          inputs scaled by their start; the fit's predictions and
//                          Jacobian (calibration_fit.cpp)
//   3. spread              the inputs a bound holds, the Jacobian's singular values: the
//                          covariance, and the combinations the data determine poorly or
//                          not at all (calibration_spread.cpp)
//   4. tables              the fitted inputs, their correlations, the points
//   5. summary             what the run says (calibration_report.cpp: 4 and 5)
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <ceres/ceres.h>

#include "study/uncertainty/calibration_cost.h"
#include "study/uncertainty/measured_response.h"
#include "twb/study/study_outcome.h"

namespace twb {

class BearingModel;

class CalibrationSteps {
 public:
  CalibrationSteps(const BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads);
  // Neither copied nor moved: problem_ holds x_'s data, and its cost function refers to
  // readings_ and response_.
  CalibrationSteps(const CalibrationSteps&) = delete;
  CalibrationSteps& operator=(const CalibrationSteps&) = delete;
  CalibrationSteps(CalibrationSteps&&) = delete;
  CalibrationSteps& operator=(CalibrationSteps&&) = delete;

  // Steps 1-5 in turn, once; the calibration stops after step 1 or 2 where out says why.
  void run();

 private:
  // Steps 1 and 2: false where the calibration stops there (out says why).
  bool weigh_readings();
  bool fit();
  void spread();     // step 3 (once: it adds to the free inputs and the weak directions)
  void tables();     // step 4
  void summarize();  // step 5

  const Scene& scene_;
  const CalibrationSettings& study_;
  const std::size_t n_;  // the fitted inputs
  StudyOutcome& out_;
  // Its tables (step 4), made with the steps: written (empty) where the calibration stops early.
  CalibrationOutcome& calibrated_;
  const ProgressReport& progress_;
  const int threads_;
  bool ran_ = false;  // run() is called once only

  // Step 1.
  std::vector<CalibrationReading> readings_;
  bool relative_ = false;  // weighed by the readings' own size, not by a deviation
  std::size_t m_ = 0;      // the readings

  // Step 2: the inputs x scaled by `scale_`, the predictions at the start and the fit,
  // the residuals there and their Jacobian in x.
  std::vector<double> scale_, x_;
  std::optional<MeasuredResponse> response_;
  MeasurementsCost* cost_ = nullptr;  // owned by problem_
  ceres::Problem problem_;
  std::vector<double> residuals_;
  std::vector<PointPrediction> at_start_;
  ceres::Solver::Summary summary_;
  std::vector<double> jacobian_;

  // Step 3: each input's value and the bound that holds it, if any; the free inputs.
  std::vector<double> value_;
  std::vector<std::string> at_bound_;
  std::vector<std::size_t> free_;
  std::size_t nf_ = 0;
  double squares_ = 0.0;  // Σ r²
  // The residuals' variance where the readings' own is not given (a relative fit).
  bool has_variance_ = false;
  double variance_ = 0.0;
  std::optional<Eigen::MatrixXd> covariance_;  // in p, over every input (zero where held)
  // Each weak direction of the free scaled inputs (over all inputs, zero where held): its
  // singular value relative to the largest, and its standard deviation (none where
  // singular). With fewer readings than inputs the directions past the readings' count
  // have no singular value at all.
  struct Weak {
    Eigen::VectorXd direction;
    double ratio = 0.0;
    std::optional<double> sd;
  };
  std::vector<Weak> weak_;
  bool singular_ = false;  // some combination the data cannot determine at all
};

}  // namespace twb
