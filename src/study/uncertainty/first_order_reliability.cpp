#include "study/uncertainty/first_order_reliability.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <boost/math/distributions/normal.hpp>
#include <fmt/format.h>

namespace twb {

namespace {

double dot(std::span<const double> a, std::span<const double> b) { return std::inner_product(a.begin(), a.end(), b.begin(), 0.0); }
double norm(std::span<const double> a) { return std::sqrt(dot(a, a)); }

// Where iterate u and gradient G stand: the design point's quantities.
void finish(DesignPoint& p, const std::vector<double>& u, const FailureLoadValue& v) {
  p.u = u;
  p.load = v.load;
  p.gradient = v.gradient;
  const double n = norm(v.gradient);
  p.alpha.assign(u.size(), 0.0);
  if (n > 0.0)  // (a vanishing gradient leaves no direction: no shares)
    for (std::size_t i = 0; i < u.size(); ++i) p.alpha[i] = -v.gradient[i] / n;
  p.beta = dot(p.alpha, u);  // u* = β α: β > 0 where the mean inputs survive
  p.probability = failure_probability(p.beta);
}

// h and its gradient where every u is zero (the inputs' medians), where both iterations start.
std::optional<FailureLoadValue> at_origin(const FailureLoadFunction& h, std::span<const double> u, DesignPoint& p) {
  std::string why;
  std::optional<FailureLoadValue> v = h(u, true, why);
  ++p.evaluations;
  if (!v) p.why = "at the inputs' medians: " + why;
  return v;
}

}  // namespace

double failure_probability(double beta) {
  return boost::math::cdf(boost::math::complement(boost::math::normal(), beta));
}

double reliability_index(double probability) {
  return boost::math::quantile(boost::math::complement(boost::math::normal(), probability));
}

DesignPoint design_point(const FailureLoadFunction& h, std::size_t inputs, double operating_load,
                         const FormSettings& settings) {
  DesignPoint p;
  std::vector<double> u(inputs, 0.0);
  std::string why;
  std::optional<FailureLoadValue> v = at_origin(h, u, p);
  if (!v) return p;
  const double tolerance = settings.load_tolerance * std::abs(operating_load);
  for (p.iterations = 1; p.iterations <= settings.max_iterations; ++p.iterations) {
    const std::vector<double>& G = v->gradient;
    const double n2 = dot(G, G);
    if (!(n2 > 0.0) || !std::isfinite(n2)) {
      p.why = "the failure load does not move with the inputs there (its gradient vanishes)";
      finish(p, u, *v);
      p.converged = false;
      return p;
    }
    const double g = v->load - operating_load;
    // u's part off the gradient's line: zero at the design point.
    const double along = dot(G, u) / n2;
    std::vector<double> off(u);
    for (std::size_t i = 0; i < inputs; ++i) off[i] -= along * G[i];
    if (std::abs(g) <= tolerance && norm(off) <= settings.direction_tolerance * std::max(1.0, norm(u))) {
      finish(p, u, *v);
      p.converged = true;
      return p;
    }
    // The HL-RF step: onto the linearized surface's nearest point.
    std::vector<double> d(inputs);
    const double reach = (dot(G, u) - g) / n2;
    for (std::size_t i = 0; i < inputs; ++i) d[i] = reach * G[i] - u[i];
    std::vector<double> target(u);
    for (std::size_t i = 0; i < inputs; ++i) target[i] += d[i];
    // Merit ½|u|² + c|g| with c above |u|/|∇g| (then d descends on it), and its slope along d.
    const double c = 2.0 * std::max(norm(u), norm(target)) / std::sqrt(n2);
    const double merit = 0.5 * dot(u, u) + c * std::abs(g);
    const double slope = dot(u, d) + c * (g > 0.0 ? 1.0 : g < 0.0 ? -1.0 : 0.0) * dot(G, d);
    std::optional<FailureLoadValue> next;
    std::vector<double> trial;
    for (double t = 1.0; t >= 1.0 / 64.0; t *= 0.5) {
      trial = u;
      for (std::size_t i = 0; i < inputs; ++i) trial[i] += t * d[i];
      // The full step with its gradient (it is taken nearly always); a shortened one
      // without, until one is taken.
      std::string trial_why;
      next = h(trial, t == 1.0, trial_why);
      ++p.evaluations;
      if (next && 0.5 * dot(trial, trial) + c * std::abs(next->load - operating_load) <= merit + 0.5 * t * std::min(slope, 0.0))
        break;
      if (!next) why = trial_why;
      next.reset();
    }
    if (!next) {
      p.why = why.empty() ? "no step along the HL-RF direction lowers the merit" : "a step's failure load: " + why;
      finish(p, u, *v);
      return p;
    }
    u = trial;
    if (next->gradient.empty()) {
      next = h(u, true, why);
      ++p.evaluations;
      if (!next) {
        p.why = "a step's failure load: " + why;
        return p;
      }
    }
    v = std::move(next);
  }
  p.why = fmt::format("not converged in {} iterations", settings.max_iterations);
  finish(p, u, *v);
  return p;
}

DesignPoint inverse_design_point(const FailureLoadFunction& h, std::size_t inputs, double probability,
                                 const FormSettings& settings) {
  DesignPoint p;
  const double beta = reliability_index(probability);
  std::vector<double> u(inputs, 0.0), previous_step;
  std::string why;
  std::optional<FailureLoadValue> v = at_origin(h, u, p);
  if (!v) return p;
  for (p.iterations = 1; p.iterations <= settings.max_iterations; ++p.iterations) {
    const double n = norm(v->gradient);
    if (!(n > 0.0) || !std::isfinite(n)) {
      p.why = "the failure load does not move with the inputs there (its gradient vanishes)";
      return p;
    }
    // The sphere's point of steepest descent of the linearized h.
    std::vector<double> next(inputs), step(inputs);
    for (std::size_t i = 0; i < inputs; ++i) next[i] = -beta * v->gradient[i] / n;
    for (std::size_t i = 0; i < inputs; ++i) step[i] = next[i] - u[i];
    if (p.iterations > 1 && norm(step) <= settings.direction_tolerance * std::max(1.0, std::abs(beta))) {
      finish(p, u, *v);
      p.beta = beta;  // on the sphere by construction
      p.probability = probability;
      p.converged = true;
      return p;
    }
    // Oscillation (a concave h): halve the step, back onto the sphere.
    if (!previous_step.empty() && norm(step) > 0.9 * norm(previous_step)) {
      for (std::size_t i = 0; i < inputs; ++i) next[i] = u[i] + 0.5 * step[i];
      const double r = norm(next);
      if (r > 0.0)
        for (double& x : next) x *= std::abs(beta) / r;
      for (std::size_t i = 0; i < inputs; ++i) step[i] = next[i] - u[i];
    }
    previous_step = step;
    u = next;
    v = h(u, true, why);
    ++p.evaluations;
    if (!v) {
      p.why = "a step's failure load: " + why;
      return p;
    }
  }
  p.why = fmt::format("not converged in {} iterations", settings.max_iterations);
  finish(p, u, *v);
  return p;
}

}  // namespace twb
