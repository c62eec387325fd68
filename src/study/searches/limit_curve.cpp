#include "study/searches/limit_curve.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>


#include "study/searches/failure_load.h"
#include "solver/kinsol_newton.h"
#include "study/study_support.h"

namespace twb {

namespace {

// Lagrange weights at `next` of the nodes: the history's parameters, then `p` (the last).
std::vector<double> extrapolation_weights(
    const std::vector<std::pair<double, std::pair<double, std::vector<double>>>>& history, double p, double next) {
  std::vector<double> nodes;
  for (const auto& h : history) nodes.push_back(h.first);
  nodes.push_back(p);
  std::vector<double> w(nodes.size(), 1.0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t j = 0; j < nodes.size(); ++j)
      if (j != i) w[i] *= (next - nodes[j]) / (nodes[i] - nodes[j]);
  return w;
}

}  // namespace

LimitCurve trace_limit_curve(BearingModel& model, CurveParameter which, LimitKind kind, double from, double to,
                             std::pair<double, std::vector<double>> crossing, const LimitCurveSettings& settings) {
  const ParameterScope load_as_given(model);
  LimitCurve out;
  out.kind = kind;
  auto shown = [&](double v) { return settings.shown ? settings.shown(v) : fmt::format("{:.6g}", v); };
  model.set_curve_parameter(which, from);
  model.set_load(crossing.first);
  out.points.push_back({from, model.describe(crossing.second), crossing.second});
  NewtonSettings newton = newton_settings(model.scene());
  newton.max_iterations = 12;
  newton.line_search = false;
  KinsolNewton corrector(model);
  const double full = (to - from) / settings.steps;
  double p = from, dp = full, slope = 0.0;
  // The last crossings (the newest last), for the predictor in the parameter.
  std::vector<std::pair<double, std::pair<double, std::vector<double>>>> history;
  while ((to - p) * (to > from ? 1.0 : -1.0) > 1e-12 * std::abs(to - from)) {
    const double next = std::abs(to - p) < std::abs(dp) ? to : p + dp;
    // (infinite where the branch has no fold there)
    const double fold = settings.fold_load ? settings.fold_load(next).value_or(INFINITY) : INFINITY;
    if (crossing.first >= fold) {
      out.ended = fmt::format("at {}: the cool branch folds at {:.2f} N, below the crossing's {:.2f} N: the fold "
                              "comes first",
                              shown(next), fold, crossing.first);
      break;
    }
    // Not past the fold: there the cool branch has no state (the secant would only wander
    // onto the fold's singular Jacobian).
    const double highest = std::min(settings.load_end, fold * (1.0 - settings.bracket_width));
    model.set_curve_parameter(which, next);
    // The crossing's load and state extrapolated through the last three crossings (the
    // curves bend: W ~ p^-1.5 for a temperature limit in speed, where the secant through
    // two is 10 % off and the parabola through three 0.1 %), so that the margin's secant
    // in load starts next to it; the last crossing's where Newton cannot start there.
    std::pair<double, std::vector<double>> here = crossing;
    bool extrapolated = false;
    if (!history.empty()) {
      extrapolated = true;
      const std::vector<double> weights = extrapolation_weights(history, p, next);
      here.first = weights.back() * crossing.first;
      for (double& v : here.second) v *= weights.back();
      for (std::size_t j = 0; j < history.size(); ++j) {
        here.first += weights[j] * history[j].second.first;
        for (std::size_t k = 0; k < here.second.size(); ++k) here.second[k] += weights[j] * history[j].second.second[k];
      }
      here.first = std::min(here.first, highest);
      // A parabola through crossings that fall steeply (the scuffing crossing of the
      // paper's bearing falls from 830 N at 136 rad/s) can predict a load a quarter of the
      // last or below, even none: outside what three points say; the last crossing's.
      if (!(here.first > 0.25 * crossing.first)) {
        here = crossing;
        here.first = std::min(here.first, highest);
        extrapolated = here.first != crossing.first;
      }
    }
    model.set_load(here.first);
    NewtonReport rep = corrector.solve(here.second, newton);
    out.solves += 1;
    if (!rep.converged && extrapolated) {
      here = crossing;  // the extrapolation left Newton's reach: the last crossing's
      model.set_load(here.first);
      rep = corrector.solve(here.second, newton);
      out.solves += 1;
    }
    if (!rep.converged) {
      model.set_curve_parameter(which, p);
      if (std::abs(dp) < std::abs(full) / 64.0) {
        out.ended = fmt::format("the branch at the crossing's load was lost between {} and {}: {}", shown(p), shown(next),
                                rep.message);
        break;
      }
      dp /= 2.0;
      continue;
    }
    std::string why;
    BearingState described;
    const std::optional<double> w = crossing_near(model, kind, here, slope, settings.bracket_width, highest,
                                                  out.solves, why, &corrector, &described);
    if (!w) {
      out.ended = fmt::format("at {}: {}", shown(next), why);
      break;
    }
    if (*w >= fold) {
      out.ended = fmt::format("at {}: the cool branch folds at {:.2f} N, below the crossing's {:.2f} N: the fold "
                              "comes first",
                              shown(next), fold, *w);
      break;
    }
    history.emplace_back(p, std::move(crossing));
    if (history.size() > 2) history.erase(history.begin());
    crossing = std::move(here);
    p = next;
    model.set_load(*w);
    out.points.push_back({p, std::move(described), crossing.second});
    // Back towards the full step after an easy one.
    if (std::abs(dp) < std::abs(full)) dp *= 2.0;
  }
  return out;
}

}  // namespace twb
