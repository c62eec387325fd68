#include "study/fold_response.h"

#include <cmath>
#include <numeric>

#include "solver/continuation_metric.h"
#include "solver/fold_system.h"
#include "study/study_support.h"

namespace twb {

namespace {

double dot(std::span<const double> a, std::span<const double> b) { return std::inner_product(a.begin(), a.end(), b.begin(), 0.0); }

}  // namespace

std::optional<SettledFold> settle_fold(BearingModel& model, const FoldPoint& found, std::string& why) {
  const FoldPoint fold = locate_fold_near(model, found.u, found.lambda, found.null_vector, newton_settings(model.scene()));
  if (fold.u.empty()) {
    why = "the fold could not be located to the solver's tolerance: " + fold.message;
    return std::nullopt;
  }
  const ParameterScope at_fold(model, fold.lambda);
  SettledFold out;
  out.load = fold.lambda;
  out.u = fold.u;
  out.null_vector = fold.null_vector;
  out.curvature = fold.curvature;
  std::vector<double> f_load(out.u.size());
  model.parameter_derivative(out.u, f_load);
  const ContinuationMetric metric = ContinuationMetric::of(model, std::abs(fold.lambda));
  const FoldSystem system(model, metric, f_load, fold.null_vector);
  std::vector<double> x = fold.u;
  x.push_back(fold.lambda / metric.parameter_scale());
  out.psi = system.left_null_vector(x);
  if (out.psi.empty()) {
    why = "the bordered matrix is singular at the fold: no left null vector";
    return std::nullopt;
  }
  out.psi_load = dot(out.psi, f_load);
  // ψᵀF_W = 0 is a branch point, not a fold: its load does not move smoothly.
  if (!(std::abs(out.psi_load) > 0.0) || !std::isfinite(out.psi_load)) {
    why = "ψᵀF_W vanishes at the fold (a branch point)";
    return std::nullopt;
  }
  return out;
}

double fold_load_derivative(InputNeighbours& n, const SettledFold& fold) {
  return -dot(fold.psi, residual_derivative(n, fold.u, fold.load)) / fold.psi_load;
}

}  // namespace twb
