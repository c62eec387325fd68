#include "study/uncertainty/fold_response.h"

#include <cmath>
#include <numeric>

#include "solver/continuation_metric.h"
#include "solver/fold_system.h"
#include "solver/sparse_lu.h"
#include "study/study_support.h"

namespace twb {

namespace {

double dot(std::span<const double> a, std::span<const double> b) { return std::inner_product(a.begin(), a.end(), b.begin(), 0.0); }

}  // namespace

std::optional<SettledFold> settle_fold(BearingModel& model, const FoldPoint& found, std::string& why, int max_iterations) {
  NewtonSettings newton = newton_settings(model.scene());
  if (max_iterations > 0) newton.max_iterations = max_iterations;
  const FoldPoint fold = locate_fold_near(model, found.u, found.lambda, found.null_vector, newton);
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

std::optional<FoldPoint> predicted_fold(BearingModel& at, BearingModel& ahead, double epsilon, const SettledFold& fold) {
  const ParameterScope at_fold(at, fold.load);
  std::vector<double> f_load(fold.u.size());
  at.parameter_derivative(fold.u, f_load);
  const ContinuationMetric metric = ContinuationMetric::of(at, std::abs(fold.load));
  std::vector<double> x = fold.u;
  x.push_back(fold.load / metric.parameter_scale());
  const FoldSystem system(at, metric, f_load, fold.null_vector);
  std::vector<double> g(x.size()), jacobian(std::size_t(system.pattern().nnz()));
  system.evaluate(x, g, jacobian);
  SparseLu lu(system.pattern(), SparseLu::Ordering::minimum_degree);
  if (!lu.factor(jacobian)) return std::nullopt;
  // G at the fold on the bearing ahead, with the same borders: one function of t.
  std::vector<double> g_ahead(x.size());
  {
    const ParameterScope keep(ahead);
    const FoldSystem moved(ahead, metric, f_load, fold.null_vector);
    moved.evaluate(x, g_ahead, {});
  }
  std::vector<double> step(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) step[i] = (g_ahead[i] - g[i]) / epsilon;
  lu.solve(step);  // −(u', μ')
  for (const double s : step)
    if (!std::isfinite(s)) return std::nullopt;
  FoldPoint predicted;
  predicted.u.resize(fold.u.size());
  for (std::size_t i = 0; i < fold.u.size(); ++i) predicted.u[i] = x[i] - step[i];
  predicted.lambda = (x.back() - step.back()) * metric.parameter_scale();
  predicted.null_vector = fold.null_vector;
  return predicted;
}

double fold_load_derivative(InputNeighbours& n, const SettledFold& fold) {
  return -dot(fold.psi, residual_derivative(n, fold.u, fold.load)) / fold.psi_load;
}

}  // namespace twb
