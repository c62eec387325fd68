// The calibration's weighted residuals (calibration_cost.h).
#include "study/uncertainty/calibration_cost.h"

#include <algorithm>
#include <exception>
#include <utility>

#include "twb/error_family.h"

namespace twb {

bool MeasurementsCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
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
    const CalibrationReading& r = readings_[k];
    const PointPrediction& at = predicted[r.point];
    residuals[k] = r.weight * (at.values[r.quantity] - r.measured);
    if (derivatives)
      for (std::size_t j = 0; j < n; ++j)
        jacobians[0][k * n + j] = r.weight * at.derivatives[r.quantity][j] * scale_[j];
  }
  last = std::move(predicted);
  return true;
}

}  // namespace twb
