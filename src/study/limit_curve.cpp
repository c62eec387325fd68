#include "study/limit_curve.h"

#include <cmath>

#include <fmt/format.h>

#include "failure_load.h"
#include "solver/kinsol_newton.h"
#include "study_support.h"

namespace twb {

LimitCurve trace_limit_curve(BearingModel& model, CurveParameter which, LimitKind kind, double from, double to,
                             std::pair<double, std::vector<double>> crossing, const LimitCurveSettings& settings) {
  LimitCurve out;
  out.kind = kind;
  model.set_curve_parameter(which, from);
  model.set_load(crossing.first);
  out.points.push_back({from, model.describe(crossing.second)});
  NewtonSettings newton = newton_settings(model.scene());
  newton.max_iterations = 12;
  newton.line_search = false;
  KinsolNewton corrector(model);
  const double full = (to - from) / settings.steps;
  double p = from, dp = full, slope = 0.0;
  while ((to - p) * (to > from ? 1.0 : -1.0) > 1e-12 * std::abs(to - from)) {
    const double next = std::abs(to - p) < std::abs(dp) ? to : p + dp;
    const std::optional<double> fold = settings.fold_load ? settings.fold_load(next) : std::nullopt;
    if (fold && crossing.first >= *fold) {
      out.ended = fmt::format("at {:.6g}: the cool branch folds at {:.2f} N, below the crossing's {:.2f} N: the fold "
                              "comes first",
                              next, *fold, crossing.first);
      break;
    }
    model.set_curve_parameter(which, next);
    model.set_load(crossing.first);
    std::vector<double> u = crossing.second;
    const NewtonReport rep = corrector.solve(u, newton);
    out.solves += 1;
    if (!rep.converged) {
      model.set_curve_parameter(which, p);
      if (std::abs(dp) < std::abs(full) / 64.0) {
        out.ended = fmt::format("the branch at the crossing's load was lost between {:.6g} and {:.6g}: {}", p, next,
                                rep.message);
        break;
      }
      dp /= 2.0;
      continue;
    }
    std::pair<double, std::vector<double>> here{crossing.first, std::move(u)};
    std::string why;
    // Not past the fold: there the cool branch has no state (the secant would only wander
    // onto the fold's singular Jacobian).
    const double highest = fold ? std::min(settings.load_end, *fold * (1.0 - settings.bracket_width)) : settings.load_end;
    const std::optional<double> w =
        crossing_near(model, kind, here, slope, settings.bracket_width, highest, out.solves, why);
    if (!w) {
      out.ended = fmt::format("at {:.6g}: {}", next, why);
      break;
    }
    if (fold && *w >= *fold) {
      out.ended = fmt::format("at {:.6g}: the cool branch folds at {:.2f} N, below the crossing's {:.2f} N: the fold "
                              "comes first",
                              next, *fold, *w);
      break;
    }
    crossing = std::move(here);
    p = next;
    model.set_load(*w);
    out.points.push_back({p, model.describe(crossing.second)});
    // Back towards the full step after an easy one.
    if (std::abs(dp) < std::abs(full)) dp *= 2.0;
  }
  return out;
}

}  // namespace twb
