// A calibration's readings (each measured value, weighed) and the weighted residuals
// Ceres Solver minimises, with their exact Jacobian (calibration.h).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ceres/ceres.h>

#include "study/uncertainty/measured_response.h"

namespace twb {

// The measured quantities' columns, in MeasuredQuantity's order.
inline constexpr const char* kMeasuredQuantityColumns[] = {"torque_Nm", "f_eff", "T_mean_C", "T_max_C"};

// One measured value: its point, its quantity, the reading (SI) and its weight 1/s.
struct CalibrationReading {
  std::size_t point = 0, quantity = 0;
  double measured = 0.0, weight = 0.0;
  std::optional<double> sd;  // SI, where the scene gives it
};

// The weighted residuals of every reading, and their Jacobian in the scaled inputs x = p/scale.
class MeasurementsCost final : public ceres::CostFunction {
 public:
  MeasurementsCost(MeasuredResponse& response, const std::vector<CalibrationReading>& readings,
                   std::vector<double> scale, const std::vector<FittedInput>& fitted)
      : response_(response), readings_(readings), scale_(std::move(scale)) {
    for (const FittedInput& f : fitted) {
      lower_.push_back(f.lower);
      upper_.push_back(f.upper);
    }
    set_num_residuals(int(readings.size()));
    mutable_parameter_block_sizes()->push_back(int(scale_.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

  mutable std::vector<PointPrediction> last;  // the last predictions that succeeded
  mutable std::string failure;               // why the last that failed did

 private:
  MeasuredResponse& response_;
  const std::vector<CalibrationReading>& readings_;
  std::vector<double> scale_, lower_, upper_;
};

}  // namespace twb
