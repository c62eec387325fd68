#include "distress_curve.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include <fmt/format.h>

#include "study_support.h"
#include "solver/fold_curve.h"
#include "study/distress_search.h"
#include "study/richardson.h"
#include "study/limit_curve.h"
#include "model/limit_thresholds.h"

namespace twb {

namespace {

// The bearing's curve parameter as the continuation's second parameter.
class BearingParameter final : public SecondParameter {
 public:
  BearingParameter(BearingModel& model, CurveParameter which) : model_(model), which_(which) {}
  double value() const override { return model_.curve_parameter(which_); }
  void set(double p) override { model_.set_curve_parameter(which_, p); }

 private:
  BearingModel& model_;
  CurveParameter which_;
};

}  // namespace

std::string fold_curve_column(CurveParameter p) {
  switch (p) {
    case CurveParameter::speed: return "speed_rad_s";
    case CurveParameter::friction_coefficient: return "friction_coefficient";
    case CurveParameter::gear_tilt: return "gear_tilt_rad";
    case CurveParameter::ambient_temperature: return "ambient_C";
    case CurveParameter::viscosity_scale: return "viscosity_scale";
    case CurveParameter::roughness: return "roughness_Rq_m";
  }
  return "parameter";
}

namespace {

// A parameter value as a user reads it.
std::string shown(CurveParameter p, double v) {
  switch (p) {
    case CurveParameter::speed: return fmt::format("{:.6g} rad/s", v);
    case CurveParameter::friction_coefficient: return fmt::format("f = {:.6g}", v);
    case CurveParameter::gear_tilt: return fmt::format("{:.6g} mrad", 1e3 * v);
    case CurveParameter::ambient_temperature: return fmt::format("{:.6g} C", v - 273.15);
    case CurveParameter::viscosity_scale: return fmt::format("viscosity x {:.6g}", v);
    case CurveParameter::roughness: return fmt::format("Rq {:.4g} um", 1e6 * v);
  }
  return fmt::format("{:.6g}", v);
}

}  // namespace

namespace {

// Every failure criterion's crossing continued across the range (limit_curve.h): from
// the first end searched that crosses it, to the other end. Its rows in fold_curve.csv
// carry the criterion's name in the fold column.
void add_limit_curves(BearingModel& model, CurveParameter which,
                      const std::vector<std::pair<double, std::vector<std::pair<double, std::vector<double>>>>>& ends,
                      std::optional<double> member, const std::string& label, StudyOutcome& out,
                      const std::function<void(const std::string&)>& say) {
  const Study& st = model.scene().study;
  LimitCurveSettings settings;
  settings.bracket_width = st.bracket_width;
  settings.load_end = st.load_end;
  // W_d along this curve's distress fold (rows of this member, sorted in the parameter),
  // interpolated linearly between its points; none outside the fold's range.
  std::vector<std::pair<double, double>> folds;
  for (const FoldCurveRow& r : out.fold_curve)
    if (r.member == member && (r.fold == "distress" || r.fold == "cusp")) folds.emplace_back(r.parameter, r.state.load);
  std::sort(folds.begin(), folds.end());
  settings.fold_load = [folds](double p) -> std::optional<double> {
    if (folds.size() < 2 || p < folds.front().first || p > folds.back().first) return std::nullopt;
    const auto hi = std::lower_bound(folds.begin(), folds.end(), std::pair{p, -1e300});
    if (hi == folds.begin()) return hi->second;
    const auto lo = hi - 1;
    return lo->second + (hi->second - lo->second) * (p - lo->first) / (hi->first - lo->first);
  };
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    const LimitKind kind = kFailureCriteria[c];
    const auto start = std::find_if(ends.begin(), ends.end(), [&](const auto& e) { return !e.second[c].second.empty(); });
    if (start == ends.end()) continue;
    const double from = start->first, to = from == st.from ? st.to : st.from;
    LimitCurve curve;
    try {
      curve = trace_limit_curve(model, which, kind, from, to, start->second[c], settings);
    } catch (const std::exception& e) {
      curve.ended = std::string("the curve could not be continued: ") + e.what();
    }
    for (const LimitCurvePoint& pt : curve.points) {
      FoldCurveRow& row = out.fold_curve.emplace_back();
      row.parameter = pt.p;
      row.fold = std::string(limit_name(kind));
      row.state = pt.state;
      row.member = member;
    }
    const std::string line =
        curve.points.empty()
            ? fmt::format("limit curve{}: {} not traced from {}: {}", label, limit_name(kind), shown(which, from),
                          curve.ended)
            : fmt::format("limit curve{}: {} crossed from {:.2f} N at {} to {:.2f} N at {} ({} points){}", label,
                          limit_name(kind), curve.points.front().state.load, shown(which, curve.points.front().p),
                          curve.points.back().state.load, shown(which, curve.points.back().p), curve.points.size(),
                          curve.ended.empty() ? std::string() : "; ended " + curve.ended);
    say(fmt::format("[curve{}] {} [{} steady solves, {:.1f} s]", label, line.substr(line.find(':') + 2), curve.solves,
                    elapsed_ms(t0) / 1000.0));
    out.summary.push_back(line);
  }
}

}  // namespace

void run_fold_curve(BearingModel& model, std::optional<double> member, const std::string& label, StudyOutcome& out,
                    const ProgressReport& progress) {
  const Study& st = model.scene().study;
  const CurveParameter which = st.curve_parameter;
  auto say = [&](const std::string& s) {
    if (progress) progress(s);
  };

  // The first fold, found and proven by the dynamics: at `from`, else at `to`.
  DistressSearchSettings settings;
  settings.load_start = st.load_start;
  settings.load_end = st.load_end;
  settings.bracket_width = st.bracket_width;
  settings.march_past_distress = false;
  std::optional<DistressSearch> first;
  double start = st.from, other = st.to;
  // Each end searched, with its criteria's crossings: where the limit curves start.
  std::vector<std::pair<double, std::vector<std::pair<double, std::vector<double>>>>> ends;
  auto search_end = [&](double end) {
    model.set_curve_parameter(which, end);
    say(fmt::format("[curve{}] the first fold at {}", label, shown(which, end)));
    DistressSearch found = search_distress(model, settings, progress);
    add_search_work(out.timings, found.counts);
    found.row.parameter = member;
    if (which != CurveParameter::speed) found.row.method = fmt::format("at {}: {}", shown(which, end), found.row.method);
    out.distress.push_back(found.row);
    for (std::size_t k = 0; k < found.cool_states; ++k) {
      out.states.push_back(found.states[k]);
      out.states.back().parameter = member;
      out.states.back().branch = "cool";
    }
    ends.emplace_back(end, found.crossing_states);
    return found;
  };
  for (const double end : {st.from, st.to}) {
    DistressSearch found = search_end(end);
    if (found.fold && found.row.distress_load) {
      first = std::move(found);
      start = end;
      other = end == st.from ? st.to : st.from;
      break;
    }
  }
  // A criterion the searched end does not cross may be crossed at the other: search it too.
  if (ends.size() == 1) {
    const auto& crossed = ends.front().second;
    const OperatingLimits limits = OperatingLimits::of(model.scene());
    const LimitValues values{.thermal = model.scene().effects.thermal};
    bool missing = false;
    for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c)
      missing = missing || (failure_margin(kFailureCriteria[c], values, limits) && crossed[c].second.empty());
    if (missing) search_end(other);
  }
  auto limit_curves = [&] { add_limit_curves(model, which, ends, member, label, out, say); };
  if (!first) {
    out.summary.push_back(fmt::format("fold curve{}: no fold between {:.6g} and {:.6g} N at either end ({} and {}): "
                                      "no sudden distress to follow",
                                      label, st.load_start, st.load_end, shown(which, st.from), shown(which, st.to)));
    limit_curves();
    return;
  }

  BearingParameter parameter(model, which);
  model.set_curve_parameter(which, start);
  FoldCurveSettings fs;
  fs.p_min = std::min(st.from, st.to);
  fs.p_max = std::max(st.from, st.to);
  // The metric's unit of the parameter: its range's size, not its value at the start
  // (which may be 0: a speed, coefficient or tilt range from zero).
  fs.p_scale = std::max(std::abs(st.from), std::abs(st.to));
  fs.direction = other > start ? +1 : -1;
  fs.arclength.newton = newton_settings(model.scene());
  fs.arclength.newton.max_iterations = 12;
  // Steps in the metric over (u, W/W_0, p/p_scale): 0.05 at first, up to 0.2; a
  // correction of up to 4 iterations counts as easy (the fold system's Jacobian carries
  // central differences, so its Newton converges a little slower than quadratically).
  fs.arclength.initial_step = 0.05;
  fs.arclength.max_step = 0.2;
  fs.arclength.max_points = 400;
  fs.arclength.easy_iterations = 4;
  const auto t0 = std::chrono::steady_clock::now();
  auto describe_at = [&](double p, double load, std::span<const double> u) {
    model.set_curve_parameter(which, p);
    model.set_load(load);
    return model.describe(u);
  };
  // W_d's error bar all along the curve: each fold again on the refined mesh
  // (study/richardson.h), from the curve's model as it stands at the first fold.
  std::optional<RefinedFoldCurve> refined;
  std::string no_bars;
  if (st.error_estimate == ErrorEstimate::richardson) {
    try {
      refined.emplace(model, which, *first->fold);
    } catch (const std::exception& e) {
      no_bars = fmt::format("fold curve{}: no error bars: the refined mesh could not be built: {}", label, e.what());
    }
  }
  FoldCurve curve;
  try {
    curve = trace_fold_curve(model, parameter, *first->fold, fs, [&](const FoldCurvePoint& pt) {
      say(fmt::format("[curve{}] {}: fold at {:.2f} N ({}) [{:.1f} s]", label, shown(which, pt.p), pt.lambda,
                      pt.curvature > 0 ? "distress" : pt.curvature < 0 ? "recovery" : "of unknown kind",
                      elapsed_ms(t0) / 1000.0));
      return true;
    });
  } catch (const std::exception& e) {
    curve.message = std::string("the curve could not be continued: ") + e.what();
  }
  if (curve.points.empty()) {
    out.summary.push_back(fmt::format("fold curve{}: not traced from {}: {}", label, shown(which, start), curve.message));
    limit_curves();
    return;
  }
  const auto n = std::size_t(model.size());
  auto add_row = [&](double p, const std::string& fold, const BearingState& state) -> FoldCurveRow& {
    FoldCurveRow& row = out.fold_curve.emplace_back();
    row.parameter = p;
    row.fold = fold;
    row.state = state;
    row.member = member;
    return row;
  };
  const auto t_bars = std::chrono::steady_clock::now();
  int with_bar = 0, folds = 0;
  std::string last_why;
  std::size_t next_turn = 0;
  std::string kind = "distress";  // the start's: W_d, proven
  for (std::size_t k = 0; k < curve.points.size(); ++k) {
    const FoldCurvePoint& pt = curve.points[k];
    // (a curvature that could not be computed, NaN, keeps the previous point's kind)
    if (pt.curvature > 0) kind = "distress";
    if (pt.curvature < 0) kind = "recovery";
    FoldCurveRow& row = add_row(pt.p, kind, describe_at(pt.p, pt.lambda, pt.u));
    if (refined) {
      ++folds;
      std::string why;
      std::optional<MeshErrorEstimate> e;
      try {
        e = refined->at(pt.p, pt.lambda, pt.u, kind == "distress" ? +1 : -1, why);
      } catch (const std::exception& failure) {
        why = failure.what();
      }
      if (e) {
        row.fine_load = e->fine_fold;
        row.extrapolated_load = e->extrapolated;
        row.discretization_error = e->error;
        ++with_bar;
      } else {
        last_why = why;
      }
    }
    const bool turns = k + 1 < curve.points.size() && pt.tangent_p * curve.points[k + 1].tangent_p < 0.0;
    if (turns && next_turn < curve.turns.size()) {
      const CurveTurn& t = curve.turns[next_turn++];
      add_row(t.p, t.cusp ? "cusp" : "turn", describe_at(t.p, t.lambda, std::span<const double>(t.point.u).first(n)));
      out.summary.push_back(
          t.cusp ? fmt::format("fold curve{}: cusp at {}, {:.2f} N: the cool and hot branches merge; on the side "
                               "without a fold the bearing heats gradually, with no sudden distress",
                               label, shown(which, t.p), t.lambda)
                 : fmt::format("fold curve{}: turns back at {}, {:.2f} N without a cusp", label, shown(which, t.p),
                               t.lambda));
    }
  }
  if (!no_bars.empty()) out.summary.push_back(no_bars);
  if (refined) {
    const std::string line =
        fmt::format("fold curve{}: error bars from the {} mesh at {} of {} folds{}", label, refined->mesh(), with_bar,
                    folds, with_bar < folds ? " (the last missing: " + last_why + ")" : std::string());
    say(fmt::format("[curve{}] {} [{:.1f} s]", label, line.substr(line.find(':') + 2), elapsed_ms(t_bars) / 1000.0));
    out.summary.push_back(line);
  }
  // Where the curve ended: past the range's end, or inside it where continuation could
  // not go on (the reason is the continuation's own, in terms of the curve parameter).
  const double last = curve.points.back().p;
  const bool finished = last < fs.p_min || last > fs.p_max;
  if (!finished)
    out.summary.push_back(fmt::format("fold curve{}: stopped at {}, inside the range: no continuation step was "
                                      "accepted there ({}); the curve may turn sharply or end there",
                                      label, shown(which, last), curve.message));
  else if (curve.turns.empty())
    out.summary.push_back(fmt::format("fold curve{}: {} points from {} to {}, no cusp in range", label,
                                      curve.points.size(), shown(which, curve.points.front().p), shown(which, last)));
  limit_curves();
}

}  // namespace twb
