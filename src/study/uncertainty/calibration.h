// Calibration to measurements (study type calibration, docs/physics.md section 18): the
// fitted inputs p that minimise Σ_k r_k², r_k = (y_k(p) − m_k)/s_k over every measured
// value m_k of a rig (s_k its standard deviation; where the scene gives none, |m_k|, a
// relative fit), by Ceres Solver's Levenberg–Marquardt within the inputs' bounds, with
// the exact sensitivities of the predictions (measured_response.h) as its Jacobian; then
// the fit's covariance (JᵀJ)⁻¹ (times the residuals' variance for a relative fit) from the
// Jacobian's singular values, which also say which combination of inputs the data
// cannot determine.
#pragma once

#include "model/bearing_model.h"
#include "twb/study/study_outcome.h"

namespace twb {

void run_calibration(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads);

}  // namespace twb
