// Calibration to measurements (docs/physics.md section 18) on the paper's bearing, tests'
// 5 x 24 mesh: rig data made by the model itself at known inputs (the oil's viscosity-
// temperature exponent G0 and the summits' radius), fitted from other starts.
//
// Tolerances, from analysis: the predictions are accurate to about 1e-9 relative (the
// solver's residual tolerance); the fitted inputs move by that over the scaled
// Jacobian's smallest singular value, which is about 1e-4 of its largest here (the summit
// radius matters little in these mostly fluid-borne states): 1e-5 relative, allowed 1e-4.
// The derivatives as in sensitivity_test.cpp: 2|fd(2Δ) − fd(Δ)| + 1e-6·|q| per unit p.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <cmath>
#include <algorithm>
#include <string>
#include <vector>

#include "../scene/scene_test_support.h"
#include "model/bearing_model.h"
#include "study/uncertainty/measured_response.h"
#include "study/study_runner.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

using testing::TempScene;

const std::vector<FittedInput> kFitted = {{"lubricant.viscosity.G0", "1", 3.545, 2.5, 5.0},
                                          {"surfaces.asperities.summit_radius", "m", 20e-6, 10e-6, 40e-6}};
const std::vector<double> kTruth = {3.9, 24e-6};

Scene point_scene() {
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                    {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "study={type: point}"});
}

std::vector<MeasuredPoint> rig_points(const std::vector<std::pair<double, double>>& load_speed) {
  std::vector<MeasuredPoint> points;
  for (const auto& [load, speed] : load_speed) {
    MeasuredPoint& p = points.emplace_back();
    p.load = load;
    p.speed = speed;
    p.values.fill(NAN);
  }
  return points;
}

// The rig's file: each point's torque (and mean temperature, unless torque_only) as the
// bearing predicts them at the truth.
std::string rig_data(const std::vector<MeasuredPoint>& points, bool torque_only = false,
                     const std::vector<double>& inputs = kTruth) {
  MeasuredResponse truth(point_scene(), kFitted, points, 1);
  std::vector<PointPrediction> at;
  std::string why;
  EXPECT_TRUE(truth.predict(inputs, false, at, why)) << why;
  std::string text = torque_only ? "load [N], speed [rad/s], torque [N m]\n"
                                 : "load [N], speed [rad/s], torque [N m], T_mean [K]\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    text += fmt::format("{:.17g}, {:.17g}, {:.17g}", points[i].load, points[i].speed, at[i].values[0]);
    text += torque_only ? "\n" : fmt::format(", {:.17g}\n", at[i].values[2]);
  }
  return text;
}

std::string calibration_scene(const std::string& data, const std::string& sd = "") {
  return fmt::format(
      "extends: {}/configs/jackson_green_2006.yaml\nmesh: {{radial_nodes: 5, circumferential_nodes: 24}}\n"
      "study: !replace\n  type: calibration\n  data: {}\n  fit:\n"
      "    lubricant.viscosity.G0: {{start: 3.545, lower: 2.5, upper: 5}}\n"
      "    surfaces.asperities.summit_radius: {{start: 20 um, lower: 10 um, upper: 40 um}}\n{}",
      TWB_SOURCE_DIR, data, sd.empty() ? "" : "  sd: " + sd + "\n");
}

StudyOutcome calibrate(const std::string& scene_text, int threads) {
  const TempScene scene(scene_text, fmt::format("_{}", threads));
  BearingModel model(load_scene(scene.path()));
  return run_study(model, {}, RunOptions{.threads = threads});
}

const std::vector<std::pair<double, double>> kPoints = {{100, 300}, {120, 300}, {140, 300},
                                                        {100, 545}, {120, 545}, {140, 545}};

TEST(Calibration, RecoversTheInputsThatMadeTheDataOnAnyThreadCount) {
  const TempScene data(rig_data(rig_points(kPoints)), "", ".csv");
  const StudyOutcome one = calibrate(calibration_scene(data.path()), 1);
  ASSERT_FALSE(one.solver_failed) << one.message;
  EXPECT_TRUE(one.message.empty()) << one.message;  // converged: run.json's outcome "ok"
  const CalibrationOutcome& one_fit = std::get<CalibrationOutcome>(one.own);
  ASSERT_EQ(one_fit.fitted.size(), 2u);
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_NEAR(one_fit.fitted[j].fitted, kTruth[j], 1e-4 * kTruth[j]) << one_fit.fitted[j].parameter;
    EXPECT_TRUE(one_fit.fitted[j].sd.has_value());
  }
  for (const CalibrationPointRow& r : one_fit.points) EXPECT_NEAR(r.residual, 0.0, 1e-6);
  EXPECT_EQ(one.states.size(), kPoints.size());  // the fitted state at each point
  // The speeds spread over two threads: the same fit, bit for bit.
  const StudyOutcome two = calibrate(calibration_scene(data.path()), 2);
  const CalibrationOutcome& two_fit = std::get<CalibrationOutcome>(two.own);
  ASSERT_EQ(two_fit.fitted.size(), 2u);
  for (std::size_t j = 0; j < 2; ++j) EXPECT_EQ(two_fit.fitted[j].fitted, one_fit.fitted[j].fitted);
  EXPECT_EQ(two.summary, one.summary);
}

// The predictions' derivatives (the fit's Jacobian) against centred differences of whole
// predictions at p ± Δ and p ± 2Δ.
TEST(Calibration, DerivativesOfThePredictionsMatchDifferences) {
  // (the second point at its own oil temperature, 40 degC: its neighbours must stand there too)
  std::vector<MeasuredPoint> points = rig_points({{120, 300}, {140, 545}});
  points[1].ambient = 313.15;
  MeasuredResponse response(point_scene(), kFitted, points, 1);
  std::vector<PointPrediction> at;
  std::string why;
  const std::vector<double> p = {3.545, 20e-6};
  ASSERT_TRUE(response.predict(p, true, at, why)) << why;
  for (std::size_t j = 0; j < p.size(); ++j) {
    auto difference = [&](double step) {
      std::vector<std::vector<double>> d(points.size(), std::vector<double>(kMeasuredQuantities));
      std::vector<PointPrediction> plus, minus;
      std::vector<double> up = p, down = p;
      up[j] += step;
      down[j] -= step;
      EXPECT_TRUE(response.predict(up, false, plus, why)) << why;
      EXPECT_TRUE(response.predict(down, false, minus, why)) << why;
      for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t q = 0; q < kMeasuredQuantities; ++q)
          d[i][q] = (plus[i].values[q] - minus[i].values[q]) / (2.0 * step);
      return d;
    };
    const double delta = 1e-3 * std::abs(p[j]);
    const auto fd = difference(delta), fd2 = difference(2.0 * delta);
    for (std::size_t i = 0; i < points.size(); ++i)
      for (std::size_t q = 0; q < kMeasuredQuantities; ++q) {
        const double allowed = 2.0 * std::abs(fd2[i][q] - fd[i][q]) + 1e-6 * std::abs(at[i].values[q] / p[j]);
        EXPECT_NEAR(at[i].derivatives[q][j], fd[i][q], allowed) << kFitted[j].path << ", point " << i << ", quantity " << q;
      }
  }
}

// With each reading's standard deviation given, the inputs' covariance is (JᵀJ)⁻¹ for J
// the weighted Jacobian of the fit's predictions, computed here again from them.
TEST(Calibration, CovarianceIsTheInverseOfTheWeightedNormalMatrix) {
  const TempScene data(rig_data(rig_points(kPoints)), "", ".csv");
  const double sd_torque = 1e-3, sd_temperature = 0.5;
  const StudyOutcome out =
      calibrate(calibration_scene(data.path(), fmt::format("{{torque: {} N m, T_mean: {} K}}", sd_torque, sd_temperature)), 1);
  ASSERT_FALSE(out.solver_failed) << out.message;
  const CalibrationOutcome& fit = std::get<CalibrationOutcome>(out.own);
  MeasuredResponse response(point_scene(), kFitted, rig_points(kPoints), 1);
  std::vector<PointPrediction> at;
  std::string why;
  const std::vector<double> fitted = {fit.fitted[0].fitted, fit.fitted[1].fitted};
  ASSERT_TRUE(response.predict(fitted, true, at, why)) << why;
  Eigen::MatrixXd J(2 * long(kPoints.size()), 2);
  for (std::size_t i = 0; i < kPoints.size(); ++i)
    for (long j = 0; j < 2; ++j) {
      J(2 * long(i), j) = at[i].derivatives[0][std::size_t(j)] / sd_torque;
      J(2 * long(i) + 1, j) = at[i].derivatives[2][std::size_t(j)] / sd_temperature;
    }
  const Eigen::MatrixXd covariance = (J.transpose() * J).inverse();
  for (long j = 0; j < 2; ++j) {
    ASSERT_TRUE(fit.fitted[std::size_t(j)].sd.has_value());
    // The same derivatives at the same inputs (the fit's own, from its last evaluation):
    // only the linear algebra's rounding differs.
    EXPECT_NEAR(*fit.fitted[std::size_t(j)].sd, std::sqrt(covariance(j, j)), 1e-6 * std::sqrt(covariance(j, j)));
  }
  ASSERT_EQ(fit.correlations.size(), 3u);
  EXPECT_NEAR(fit.correlations[1].correlation, covariance(0, 1) / std::sqrt(covariance(0, 0) * covariance(1, 1)), 1e-6);
}

// A fit stopped by study.max_iterations before it converged says so where a script
// looks (the outcome's message: run.json's outcome, Results.message), and keeps the
// inputs it reached (a usable fit, not a solver failure).
TEST(Calibration, AFitStoppedShortSaysSo) {
  const TempScene data(rig_data(rig_points(kPoints)), "", ".csv");
  const StudyOutcome out = calibrate(calibration_scene(data.path()) + "  max_iterations: 1\n", 1);
  ASSERT_FALSE(out.solver_failed) << out.message;
  EXPECT_NE(out.message.find("the calibration stopped before converging"), std::string::npos) << out.message;
  const std::vector<CalibrationRow>& fitted = std::get<CalibrationOutcome>(out.own).fitted;
  ASSERT_EQ(fitted.size(), 2u);
  // One step from the start: moved, and not yet at the truth.
  EXPECT_NE(fitted[0].fitted, fitted[0].start);
  EXPECT_GT(std::abs(fitted[0].fitted - kTruth[0]), 1e-4 * kTruth[0]);
}

// One torque reading cannot determine two inputs: the fit says which combination it
// cannot, and gives neither a standard deviation. (The reading is the bearing's at the
// fit's start, so that the fit stays there: from elsewhere it would slide along the
// line of exact fits until a bound holds one input, and the other is then determined.)
TEST(Calibration, OneReadingForTwoInputsIsNotIdentifiable) {
  const TempScene data(rig_data(rig_points({{120, 300}}), true, {kFitted[0].start, kFitted[1].start}), "", ".csv");
  const StudyOutcome out = calibrate(calibration_scene(data.path()), 1);
  ASSERT_FALSE(out.solver_failed) << out.message;
  const CalibrationOutcome& fit = std::get<CalibrationOutcome>(out.own);
  for (const CalibrationRow& r : fit.fitted) EXPECT_FALSE(r.sd.has_value()) << r.parameter;
  EXPECT_TRUE(fit.correlations.empty());
  EXPECT_TRUE(std::any_of(out.summary.begin(), out.summary.end(), [](const std::string& s) {
    return s.find("the data cannot determine the combination lubricant.viscosity.G0") != std::string::npos;
  })) << fmt::format("{}", fmt::join(out.summary, "\n"));
}

// Each reading weighed by its own standard deviation (the data's torque_sd and
// T_mean_sd columns): a seventh point whose torque is 50 % off, given a deviation 10⁵
// times the others', leaves the fit at the truth (its pull on the inputs is of order
// (10⁻⁵)² of the others' and the truth fits them exactly), and every reading's sd is its
// own in calibration_points; the same point with the others' deviation pulls the fit
// off the truth by more than ten times the tolerance (by about 1 %).
TEST(Calibration, EachReadingIsWeighedByItsOwnDeviation) {
  std::vector<std::pair<double, double>> points = kPoints;
  points.emplace_back(130, 545);
  const std::string made = rig_data(rig_points(points));
  auto data_with = [&](double outlier_sd) {
    std::string text;
    std::size_t line = 0, start = 0;
    for (std::size_t end = made.find('\n'); end != std::string::npos; start = end + 1, end = made.find('\n', start), ++line) {
      std::string row = made.substr(start, end - start);
      if (line == 0) {
        text += row + ", torque_sd [N m], T_mean_sd [K]\n";
        continue;
      }
      const bool outlier = line == points.size();
      if (outlier) {
        // The torque (the third field) 50 % off.
        const std::size_t a = row.find(", ", row.find(", ") + 2) + 2, b = row.find(',', a);
        row = row.substr(0, a) + fmt::format("{:.17g}", 1.5 * std::stod(row.substr(a, b - a))) + row.substr(b);
      }
      text += row + fmt::format(", {:.17g}, 0.01\n", outlier ? outlier_sd : 1e-4);
    }
    return text;
  };
  const TempScene loose(data_with(10.0), "_loose", ".csv"), tight(data_with(1e-4), "_tight", ".csv");
  const StudyOutcome out = calibrate(calibration_scene(loose.path()), 1);
  ASSERT_FALSE(out.solver_failed) << out.message;
  const CalibrationOutcome& fit = std::get<CalibrationOutcome>(out.own);
  ASSERT_EQ(fit.fitted.size(), 2u);
  for (std::size_t j = 0; j < 2; ++j)
    EXPECT_NEAR(fit.fitted[j].fitted, kTruth[j], 1e-4 * kTruth[j]) << fit.fitted[j].parameter;
  ASSERT_EQ(fit.points.size(), 2 * points.size());
  for (const CalibrationPointRow& r : fit.points) {
    const bool torque = r.quantity == "torque_Nm";
    const double expected = !torque ? 0.01 : r.point == long(points.size()) ? 10.0 : 1e-4;  // points count from 1
    ASSERT_TRUE(r.sd.has_value());
    EXPECT_EQ(*r.sd, expected) << r.point << " " << r.quantity;
  }
  const StudyOutcome pulled = calibrate(calibration_scene(tight.path()), 1);
  ASSERT_FALSE(pulled.solver_failed) << pulled.message;
  EXPECT_GT(std::abs(std::get<CalibrationOutcome>(pulled.own).fitted[0].fitted - kTruth[0]), 10 * 1e-4 * kTruth[0]);
}

// A measured point past the fold of the branch continued from the light load (on this
// mesh the paper's bearing folds below 200 N at 545 rad/s) has no prediction: the study
// says which line, rather than fitting the hot branch's state there.
TEST(Calibration, APointPastTheFoldIsRefusedAtItsLine) {
  const TempScene data("load [N], speed [rad/s], torque [N m]\n140, 545, 0.05\n200, 545, 0.06\n", "", ".csv");
  const StudyOutcome out = calibrate(calibration_scene(data.path()), 1);
  EXPECT_TRUE(out.solver_failed);
  EXPECT_NE(out.message.find("the measured point of line 3 (200 N, 545 rad/s) lies past the fold"), std::string::npos)
      << out.message;
}

}  // namespace
}  // namespace twb
