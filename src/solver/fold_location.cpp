#include "solver/fold_location.h"

#include <cmath>
#include <functional>

#include <boost/math/tools/toms748_solve.hpp>

#include "solver/arclength_system.h"
#include "solver/fold_system.h"
#include "twb/error_family.h"

namespace twb {

const char* to_string(FoldMethod method) {
  switch (method) {
    case FoldMethod::minimally_augmented: return "minimally augmented Newton";
    case FoldMethod::arclength_bracket: return "t_lambda = 0 bracketed along the arclength";
    case FoldMethod::interpolated: return "interpolated t_lambda (not converged)";
  }
  return "?";
}

namespace {

std::vector<double> between(std::span<const double> a, std::span<const double> b, double tau) {
  std::vector<double> x(a.size());
  for (std::size_t k = 0; k < a.size(); ++k) x[k] = a[k] + tau * (b[k] - a[k]);
  return x;
}

// x + s·d
std::vector<double> along(std::span<const double> x, std::span<const double> d, double s) {
  std::vector<double> y(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) y[k] = x[k] + s * d[k];
  return y;
}

// Where t_μ, linear between the two points, vanishes.
double interpolated_zero(const FoldBracket& br) {
  const double a = br.t_a.back(), b = br.t_b.back();
  return a / (a - b);
}

void unit(std::vector<double>& v, const ContinuationMetric& metric) {
  const double size = metric.state_norm(v);
  for (double& c : v) c /= size;
}

// Newton on [F; g] from x = (u, μ), the borders F_λ at u and the state direction t; on
// success fold holds the fold (u, λ, null vector, curvature when asked) and x the root.
// `accept` may still refuse the root (with fold.message saying why).
bool augmented_newton(SteadySystem& system, const ContinuationMetric& metric, std::vector<double>& x,
                      std::span<const double> direction, const NewtonSettings& newton, bool with_curvature,
                      const std::function<bool(std::span<const double>)>& accept, FoldPoint& fold) {
  const auto n = std::size_t(system.size());
  system.set_parameter(x[n] * metric.parameter_scale());
  std::vector<double> f_lambda(n);
  system.parameter_derivative(std::span<const double>(x).first(n), f_lambda);
  try {
    FoldSystem augmented(system, metric, f_lambda, direction);
    KinsolNewton solver(augmented);
    const NewtonReport rep = solver.solve(x, newton);
    fold.iterations = rep.iterations;
    if (!rep.converged) {
      fold.message = "minimally augmented Newton failed: " + rep.message;
      return false;
    }
    if (accept && !accept(x)) return false;
    auto [null_vector, curvature] = with_curvature ? augmented.null_vector_and_curvature(x)
                                                   : std::pair{augmented.null_vector(x), fold.curvature};
    if (null_vector.size() != n) {
      fold.message = "minimally augmented Newton: the bordered matrix is singular at its root";
      return false;
    }
    fold.u.assign(x.begin(), x.begin() + std::ptrdiff_t(n));
    fold.lambda = augmented.lambda_of(x);
    fold.null_vector = std::move(null_vector);
    fold.residual_norm = rep.residual_norm;
    fold.method = FoldMethod::minimally_augmented;
    fold.curvature = curvature;
    return true;
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    fold.message = std::string("minimally augmented Newton failed: ") + e.what();
    return false;
  }
}

bool minimally_augmented(SteadySystem& system, const ContinuationMetric& metric, const FoldBracket& br,
                         const NewtonSettings& newton, FoldPoint& fold) {
  const auto n = std::size_t(system.size());
  const double tau = interpolated_zero(br);
  std::vector<double> x = between(br.x_a, br.x_b, tau);
  const std::vector<double> t = between(br.t_a, br.t_b, tau);
  // A root far outside the bracket belongs to another fold (or to nothing real).
  const double reach = 2.0 * std::max(br.step, metric.norm(along(br.x_b, br.x_a, -1.0)));
  const auto inside = [&](std::span<const double> root) {
    if (metric.norm(along(root, br.x_a, -1.0)) <= reach) return true;
    fold.message = "minimally augmented Newton converged outside the bracket";
    return false;
  };
  return augmented_newton(system, metric, x, std::span<const double>(t).first(n), newton, false, inside, fold);
}

bool arclength_bracket(SteadySystem& system, const ContinuationMetric& metric, const FoldBracket& br,
                       const NewtonSettings& newton, const FoldSettings& settings, FoldPoint& fold) {
  const auto n = std::size_t(system.size());
  try {
    ArclengthSystem arc(system, metric);
    KinsolNewton solver(arc);
    std::vector<double> x, t;
    NewtonReport rep;
    long evaluations = 0;
    // t_μ along the hyperplanes normal to t_a: continuous in s, of opposite signs at
    // s = 0 (x_a) and s = step (x_b).
    const auto t_mu = [&](double s) {
      arc.set_step(br.x_a, br.t_a, s);
      x = along(br.x_a, br.t_a, s);
      rep = solver.solve(x, newton);
      ++evaluations;
      if (!rep.converged) throw SolverFailure("a correction inside the bracket failed: " + rep.message, rep.flag);
      t = arc.tangent(x, br.t_a);
      return t[n];
    };
    // Near the fold λ(s) ≈ λ* − ½κ(s − s*)²: a bracket √tol·Δs wide puts λ within
    // ½·tol·κΔs² of λ*, the corrector's own accuracy when the steps resolve the branch's
    // curvature (κΔs = O(1) or less); the state is then within √tol·Δs.
    const double width = std::sqrt(newton.residual_tolerance) * br.step;
    auto max_iterations = boost::uintmax_t(settings.max_bracket_evaluations);
    const auto [lo, hi] = boost::math::tools::toms748_solve(
        t_mu, 0.0, br.step, br.t_a.back(), br.t_b.back(),
        [width](double a, double b) { return std::abs(b - a) <= width; }, max_iterations);
    t_mu(0.5 * (lo + hi));
    fold.iterations = evaluations;
    fold.u.assign(x.begin(), x.begin() + std::ptrdiff_t(n));
    fold.lambda = arc.lambda_of(x);
    fold.null_vector.assign(t.begin(), t.begin() + std::ptrdiff_t(n));
    unit(fold.null_vector, metric);
    fold.residual_norm = rep.residual_norm;
    fold.method = FoldMethod::arclength_bracket;
    if (hi - lo > width) fold.message += "; the bracket did not narrow to its tolerance";
    return true;
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    fold.message += std::string("; bracketing t_lambda = 0 failed: ") + e.what();
    return false;
  }
}

}  // namespace

FoldPoint locate_fold_near(SteadySystem& system, std::span<const double> u, double lambda,
                           std::span<const double> null_guess, NewtonSettings newton, double load_accuracy) {
  FoldPoint fold;
  if (null_guess.size() != u.size() || Index(u.size()) != system.size()) {
    fold.message = "locate_fold_near: the guess and its null vector must have one entry per unknown";
    return fold;
  }
  const ParameterScope at_guess(system, lambda);
  const ContinuationMetric metric = ContinuationMetric::of(system, std::abs(lambda));
  std::vector<double> x(u.begin(), u.end());
  x.push_back(lambda / metric.parameter_scale());
  if (load_accuracy > 0.0) {
    newton.watched = Index(u.size());
    newton.watched_step = load_accuracy / metric.parameter_scale();
  }
  if (!augmented_newton(system, metric, x, null_guess, newton, true, {}, fold)) {
    FoldPoint failed;
    failed.message = fold.message;
    failed.iterations = fold.iterations;
    fold = std::move(failed);
  }
  return fold;
}

FoldPoint locate_fold(SteadySystem& system, const ContinuationMetric& metric, const FoldBracket& bracket,
                      const NewtonSettings& newton, const FoldSettings& settings) {
  const ParameterScope kept(system);
  FoldPoint fold;
  const auto n = std::size_t(system.size());
  if (!(settings.minimally_augmented && minimally_augmented(system, metric, bracket, newton, fold)) &&
      !arclength_bracket(system, metric, bracket, newton, settings, fold)) {
    const std::vector<double> x = between(bracket.x_a, bracket.x_b, interpolated_zero(bracket));
    const std::vector<double> t = between(bracket.t_a, bracket.t_b, interpolated_zero(bracket));
    fold.u.assign(x.begin(), x.begin() + std::ptrdiff_t(n));
    fold.lambda = x[n] * metric.parameter_scale();
    fold.null_vector.assign(t.begin(), t.begin() + std::ptrdiff_t(n));
    unit(fold.null_vector, metric);
    fold.method = FoldMethod::interpolated;
  }
  return fold;
}

}  // namespace twb
