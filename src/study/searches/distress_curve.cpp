#include "study/searches/distress_curve.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <exception>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "study/study_support.h"
#include "solver/fold_curve.h"
#include "study/searches/distress_search.h"
#include "study/accuracy/fold_curve_bars.h"
#include "study/searches/fold_curve_feed.h"
#include "study/accuracy/richardson.h"
#include "study/accuracy/search_error_bars.h"
#include "study/searches/limit_curve.h"
#include "study/searches/limit_curve_jobs.h"
#include "study/parallel/parallel.h"
#include "model/failure_margins.h"
#include "twb/error_family.h"

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

// Runs every piece on up to `threads` threads; the first exception (in the pieces'
// order) is thrown again once all are done, as run_in_parallel does, but only after
// every piece's work is counted. The KLU factorizations of pieces run on
// other threads than the caller's are added to `timings` (the caller counts its own
// thread's).
template <class Piece>
void run_pieces(std::size_t count, int threads, RunTimings& timings, const Piece& piece) {
  std::vector<std::exception_ptr> failed(count);
  std::vector<long> factorizations(count, 0);
  const std::thread::id caller = std::this_thread::get_id();
  run_in_parallel(count, threads, [&](std::size_t i) {
    const SparseLu::Counts before = SparseLu::thread_counts();
    try {
      piece(i);
    } catch (...) {
      failed[i] = std::current_exception();
    }
    if (std::this_thread::get_id() != caller) factorizations[i] = SparseLu::thread_counts().factored_since(before);
  });
  for (long f : factorizations) timings.klu_factorizations += f;
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

// Both ends of a curve's range searched for their first fold.
struct CurveEnds {
  std::optional<DistressSearch> from, to;
};

// Each end searched on a model of its own (`model` at `from`, `other` at `to`): `from`
// always, `to` where `from` has no proven fold or does not cross every criterion the
// scene applies (a limit curve starts from the end that crosses it). With a thread to
// spare both are searched at once and `to`'s search is dropped where it is not needed:
// the same results either way. Then the kept ends' failure loads with their error bars,
// to the study's tolerance (search_error_bars.h), each end on a thread of its own.
CurveEnds search_ends(BearingModel& model, BearingModel& other, const std::string& label,
                      const ProgressReport& progress, int threads, RunTimings& timings) {
  const Study& st = model.scene().study;
  const DistressCurveSettings& asked = std::get<DistressCurveSettings>(st.settings);
  DistressSearchSettings settings = range_settings(asked.search);
  settings.march_past_distress = false;
  settings.failure_error_bars = asked.error_bars.estimate != ErrorEstimate::none;
  settings.error_tolerance = asked.error_bars.tolerance;
  const PerCriterion<bool> in_force =
      criteria_in_force(OperatingLimits::of(model.scene()), model.scene().effects.thermal);
  auto needs_other_end = [&](const DistressSearch& found) {
    if (!(found.fold && found.row.distress_load)) return true;
    for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c)
      if (in_force[c] && (c >= found.crossing_states.size() || found.crossing_states[c].second.empty())) return true;
    return false;
  };
  CurveEnds ends;
  auto search_end = [&](std::size_t i) {
    BearingModel& m = i == 0 ? model : other;
    const double end = i == 0 ? asked.from : asked.to;
    m.set_curve_parameter(asked.curve_parameter, end);
    if (progress) progress(fmt::format("[curve{}] the first fold at {}", label, shown_parameter(st, end)));
    (i == 0 ? ends.from : ends.to) = search_distress(m, settings, progress);
  };
  if (threads > 1) {
    run_pieces(2, threads, timings, search_end);
    if (!needs_other_end(*ends.from)) ends.to.reset();
  } else {
    search_end(0);
    if (needs_other_end(*ends.from)) search_end(1);
  }
  run_pieces(ends.to ? 2 : 1, threads, timings, [&](std::size_t i) {
    estimate_failure_errors(i == 0 ? model : other, settings, i == 0 ? *ends.from : *ends.to, progress, nullptr);
  });
  return ends;
}

// An end's search in the outcome: its row in distress.csv (tagged with the family member,
// and with the parameter's value where it is not the speed), its cool-branch states.
void record_end(DistressSearch& found, double end, const Study& st, std::optional<double> member,
                StudyOutcome& out) {
  const DistressCurveSettings& asked = std::get<DistressCurveSettings>(st.settings);
  add_search_work(out.timings, found.counts);
  found.row.parameters = member ? std::vector<double>{*member} : std::vector<double>{};
  if (asked.curve_parameter != CurveParameter::speed) found.row.method = fmt::format("at {}: {}", shown_parameter(st, end), found.row.method);
  out.distress.push_back(found.row);
  for (std::size_t k = 0; k < found.cool_states; ++k) {
    out.states.push_back(found.states[k]);
    out.states.back().parameters = found.row.parameters;
    out.states.back().branch = Branch::cool;
  }
}

// The fold's continuation from `start` towards `other` across the study's range.
FoldCurveSettings fold_curve_settings(const Scene& scene, double start, double other) {
  const DistressCurveSettings& asked = std::get<DistressCurveSettings>(scene.study.settings);
  FoldCurveSettings fs;
  fs.p_min = std::min(asked.from, asked.to);
  fs.p_max = std::max(asked.from, asked.to);
  // The metric's unit of the parameter: its range's size, not its value at the start
  // (which may be 0: a speed, coefficient or tilt range from zero).
  fs.p_scale = std::max(std::abs(asked.from), std::abs(asked.to));
  fs.direction = other > start ? +1 : -1;
  fs.arclength.newton = newton_settings(scene);
  fs.arclength.newton.max_iterations = 12;
  // Steps in the metric over (u, W/W_0, p/p_scale): 0.05 at first, up to 0.2; a
  // correction of up to 4 iterations counts as easy (the fold system's Jacobian carries
  // central differences, so its Newton converges a little slower than quadratically).
  fs.arclength.initial_step = 0.05;
  fs.arclength.max_step = 0.2;
  fs.arclength.max_points = 400;
  fs.arclength.easy_iterations = 4;
  return fs;
}

// The limit curves' settings from the study's (each curve's W_d is set once the fold
// curve is traced).
LimitCurveSettings limit_curve_settings(const Study& st) {
  const DistressCurveSettings& asked = std::get<DistressCurveSettings>(st.settings);
  LimitCurveSettings settings;
  settings.bracket_width = asked.search.bracket_width;
  settings.load_end = asked.search.loads.end;
  settings.error_bars = asked.error_bars.estimate != ErrorEstimate::none;
  settings.tolerance = asked.error_bars.tolerance;
  settings.shown = [st](double p) { return shown_parameter(st, p); };
  return settings;
}

// The folds' error bars in their rows (row_of[k] the row of the curve's point k), and what
// they came to in the summary and the progress (`seconds` since the pieces began).
void add_fold_bars(const FoldCurveBars& bars, const FoldCurve& curve, const std::vector<std::size_t>& row_of,
                   const Study& st, const std::string& label, double tolerance, double seconds,
                   StudyOutcome& out, const std::function<void(const std::string&)>& say) {
  const std::size_t points = curve.points.size();
  std::vector<FoldCurveRow>& rows = out.own_part<DistressCurveOutcome>().rows;
  for (std::size_t k = 0; k < points; ++k)
    if (const auto& e = bars[k].estimate) put_bar(rows[row_of[k]], *e);
  const BarsSummary summary = bars_summary(
      bars.first(points), tolerance, "folds", [&](std::size_t k) { return shown_parameter(st, curve.points[k].p); },
      "fold curve" + label);
  say(fmt::format("[curve{}] {} [{:.1f} s]", label, summary.phrase, seconds));
  out.summary.push_back(fmt::format("fold curve{}: {}", label, summary.phrase));
  if (summary.warning) out.summary.push_back(*summary.warning);
}

// Where the curve ended: inside the range where continuation could not go on (the reason
// is the continuation's own, in terms of the curve parameter), or past its end without a
// cusp (a cusp has its own line); none otherwise.
std::optional<std::string> where_the_curve_ended(const FoldCurve& curve, const FoldCurveSettings& fs,
                                                 const Study& st, const std::string& label) {
  const double last = curve.points.back().p;
  if (!(last < fs.p_min || last > fs.p_max))
    return fmt::format("fold curve{}: stopped at {}, inside the range: no continuation step was accepted there ({}); "
                       "the curve may turn sharply or end there",
                       label, shown_parameter(st, last), curve.message);
  if (curve.turns.empty())
    return fmt::format("fold curve{}: {} points from {} to {}, no cusp in range", label, curve.points.size(),
                       shown_parameter(st, curve.points.front().p), shown_parameter(st, last));
  return std::nullopt;
}

}  // namespace

void run_fold_curve(BearingModel& model, std::optional<double> member, const std::string& label, StudyOutcome& out,
                    const ProgressReport& progress, int threads) {
  const Study& st = model.scene().study;
  const DistressCurveSettings& asked = std::get<DistressCurveSettings>(st.settings);
  const CurveParameter which = asked.curve_parameter;
  // The rows this curve adds to fold_curve.csv.
  std::vector<FoldCurveRow>& rows = out.own_part<DistressCurveOutcome>().rows;
  auto say = [&](const std::string& s) {
    if (progress) progress(s);
  };

  // The first fold, found and proven by the dynamics: at `from`, else at `to`.
  BearingModel other_model(model.scene());
  CurveEnds searched = search_ends(model, other_model, label, progress, threads, out.timings);
  std::optional<DistressSearch>&at_from = searched.from, &at_to = searched.to;  // (the names of the code below)
  // Each end searched, with its criteria's crossings: where the limit curves start.
  std::vector<std::pair<double, Crossings>> ends;
  auto take = [&](DistressSearch& found, double end) {
    record_end(found, end, st, member, out);
    ends.emplace_back(end, found.crossing_states);
  };
  const DistressSearch* first = nullptr;
  double start = asked.from, other = asked.to;
  take(*at_from, asked.from);
  if (at_from->fold && at_from->row.distress_load) first = &*at_from;
  if (at_to) {
    take(*at_to, asked.to);
    if (!first && at_to->fold && at_to->row.distress_load) {
      first = &*at_to;
      start = asked.to;
      other = asked.from;
    }
  }

  std::vector<LimitCurveJob> jobs = limit_curve_jobs(asked, ends);
  LimitCurveSettings limit_settings = limit_curve_settings(st);
  auto add_limit_curves = [&] {
    for (const LimitCurveJob& job : jobs) add_limit_curve(job, st, member, label, asked.error_bars.tolerance, out, say);
  };
  auto limit_curves_alone = [&] {
    limit_settings.fold_load = distress_fold_of(rows, member);
    run_pieces(jobs.size(), threads, out.timings, [&](std::size_t i) { trace_job(model.scene(), which, limit_settings, jobs[i]); });
    add_limit_curves();
  };
  if (!first) {
    out.summary.push_back(fmt::format("fold curve{}: no fold between {:.6g} and {:.6g} N at either end ({} and {}): "
                                      "no sudden distress to follow",
                                      label, asked.search.loads.start, asked.search.loads.end,
                                      shown_parameter(st, asked.from), shown_parameter(st, asked.to)));
    limit_curves_alone();
    return;
  }

  BearingParameter parameter(model, which);
  model.set_curve_parameter(which, start);
  const FoldCurveSettings fs = fold_curve_settings(model.scene(), start, other);
  const auto t0 = std::chrono::steady_clock::now();
  auto describe_at = [&](double p, double load, std::span<const double> u) {
    model.set_curve_parameter(which, p);
    model.set_load(load);
    return model.describe(u);
  };
  FoldCurve curve;
  const auto n = std::size_t(model.size());
  auto add_row = [&](double p, FoldKind fold, const BearingState& state) {
    FoldCurveRow& row = rows.emplace_back();
    row.parameter = p;
    row.fold = fold;
    row.state = state;
    row.member = member;
    return rows.size() - 1;
  };
  // Each point's fold kind (+1 distress, -1 recovery) and row.
  std::vector<int> kind_of;
  std::vector<std::size_t> row_of;
  FoldCurveFeed feed;
  // The curve, its rows, each fold's kind, the turns; then W_d along it for the limit
  // curves (set before the feed ends: they wait for that).
  auto trace = [&] {
    const FeedEnds ends(feed);
    int kind = +1;  // the start's: W_d, proven
    try {
      curve = trace_fold_curve(model, parameter, *first->fold, fs, [&](const FoldCurvePoint& pt) {
        say(fmt::format("[curve{}] {}: fold at {:.2f} N ({}) [{:.1f} s]", label, shown_parameter(st, pt.p), pt.lambda,
                        pt.curvature > 0 ? "distress" : pt.curvature < 0 ? "recovery" : "of unknown kind",
                        elapsed_ms(t0) / 1000.0));
        // (a curvature that could not be computed, NaN, keeps the previous point's kind)
        if (pt.curvature > 0) kind = +1;
        if (pt.curvature < 0) kind = -1;
        kind_of.push_back(kind);
        feed.add(pt, kind);
        return true;
      });
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      curve.message = std::string("the curve could not be continued: ") + e.what();
    }
    std::size_t next_turn = 0;
    for (std::size_t k = 0; k < curve.points.size(); ++k) {
      const FoldCurvePoint& pt = curve.points[k];
      row_of.push_back(add_row(pt.p, kind_of[k] > 0 ? FoldKind::distress : FoldKind::recovery,
                               describe_at(pt.p, pt.lambda, pt.u)));
      const bool turns = k + 1 < curve.points.size() && pt.tangent_p * curve.points[k + 1].tangent_p < 0.0;
      if (turns && next_turn < curve.turns.size()) {
        const CurveTurn& t = curve.turns[next_turn++];
        add_row(t.p, t.cusp ? FoldKind::cusp : FoldKind::turn, describe_at(t.p, t.lambda, std::span<const double>(t.point.u).first(n)));
        out.summary.push_back(
            t.cusp ? fmt::format("fold curve{}: cusp at {}, {:.2f} N: the cool and hot branches merge; on the side "
                                 "without a fold the bearing heats gradually, with no sudden distress",
                                 label, shown_parameter(st, t.p), t.lambda)
                   : fmt::format("fold curve{}: turns back at {}, {:.2f} N without a cusp", label, shown_parameter(st, t.p),
                                 t.lambda));
      }
    }
    limit_settings.fold_load = distress_fold_of(rows, member);
  };

  // On `threads` threads: the curve; W_d's error bar all along it (fold_curve_bars.h:
  // chains that follow the curve as it is traced); then every limit curve. Each piece on
  // models of its own.
  const bool bars = asked.error_bars.estimate != ErrorEstimate::none;
  const auto most_points = std::size_t(fs.arclength.max_points) + 1;
  // The chains' bearings from the scene as it stands before the curve: the trace sets
  // its model's curve parameter while they are built (and a roughness rescales from
  // where it stands, so a copy taken mid-trace would depend on timing).
  FoldCurveBars bar_of(model.scene(), which, *first->fold, bars ? most_points : 0, asked.error_bars.tolerance,
                       [&](const std::string& s) { say(fmt::format("[curve{}] {}", label, s)); });
  const std::size_t chains = bar_of.chains();
  const auto t_pieces = std::chrono::steady_clock::now();
  run_pieces(1 + chains + jobs.size(), threads, out.timings, [&](std::size_t i) {
    if (i == 0) {
      trace();
    } else if (i <= chains) {
      bar_of.run_chain(i - 1, feed);
    } else {
      feed.wait_for_end();
      trace_job(model.scene(), which, limit_settings, jobs[i - 1 - chains]);
    }
  });
  if (curve.points.empty()) {
    out.summary.push_back(fmt::format("fold curve{}: not traced from {}: {}", label, shown_parameter(st, start), curve.message));
    add_limit_curves();
    return;
  }
  if (bars) add_fold_bars(bar_of, curve, row_of, st, label, asked.error_bars.tolerance, elapsed_ms(t_pieces) / 1000.0, out, say);
  if (const std::optional<std::string> line = where_the_curve_ended(curve, fs, st, label)) out.summary.push_back(*line);
  add_limit_curves();
}

}  // namespace twb
