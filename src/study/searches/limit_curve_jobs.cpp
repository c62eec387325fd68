#include "study/searches/limit_curve_jobs.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "model/limit_thresholds.h"
#include "study/accuracy/richardson.h"
#include "study/study_support.h"
#include "twb/error_family.h"
#include "twb/results/run_axes.h"

namespace twb {

std::string shown_parameter(const Study& st, double v) {
  switch (std::get<DistressCurveSettings>(st.settings).curve_parameter) {
    case CurveParameter::speed: return speed_text(v, st.speeds_in_rpm);
    case CurveParameter::friction_coefficient: return fmt::format("f = {:.6g}", v);
    case CurveParameter::gear_tilt: return fmt::format("{:.6g} mrad", 1e3 * v);
    case CurveParameter::ambient_temperature: return fmt::format("{:.6g} C", v - 273.15);
    case CurveParameter::viscosity_scale: return fmt::format("viscosity x {:.6g}", v);
    case CurveParameter::roughness: return fmt::format("Rq {:.4g} um", 1e6 * v);
  }
  return fmt::format("{:.6g}", v);
}

std::vector<LimitCurveJob> limit_curve_jobs(const DistressCurveSettings& curve,
                                            const std::vector<std::pair<double, Crossings>>& ends) {
  std::vector<LimitCurveJob> jobs;
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c) {
    // (a search that failed at its light load has no crossings at all)
    const auto start = std::find_if(ends.begin(), ends.end(),
                                    [&](const auto& e) { return c < e.second.size() && !e.second[c].second.empty(); });
    if (start == ends.end()) continue;
    LimitCurveJob& job = jobs.emplace_back();
    job.kind = kFailureCriteria[c];
    job.from = start->first;
    job.to = job.from == curve.from ? curve.to : curve.from;
    job.start = start->second[c];
  }
  return jobs;
}

std::function<std::optional<double>(double)> distress_fold_of(const std::vector<FoldCurveRow>& rows,
                                                              std::optional<double> member) {
  std::vector<std::pair<double, double>> folds;
  for (const FoldCurveRow& r : rows)
    if (r.member == member && (r.fold == FoldKind::distress || r.fold == FoldKind::cusp)) folds.emplace_back(r.parameter, r.state.load);
  std::sort(folds.begin(), folds.end());
  return [folds](double p) -> std::optional<double> {
    if (folds.size() < 2 || p < folds.front().first || p > folds.back().first) return std::nullopt;
    const auto hi = std::lower_bound(folds.begin(), folds.end(), std::pair{p, -1e300});
    if (hi == folds.begin()) return hi->second;
    const auto lo = hi - 1;
    return lo->second + (hi->second - lo->second) * (p - lo->first) / (hi->first - lo->first);
  };
}

namespace {

// Each point's crossing along the mesh sequence (crossing_sequence), on bearings of the
// job's own: one per mesh, built when a point first needs it and moved to each point's
// parameter.
void bar_points(const Scene& scene, CurveParameter which, const LimitCurveSettings& settings, LimitCurveJob& job) {
  job.bars.resize(job.curve.points.size());
  if (job.bars.empty()) return;
  std::optional<BearingModel> coarse;
  try {
    coarse.emplace(scene);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    for (FoldBar& bar : job.bars) bar.why = e.what();
    return;
  }
  std::vector<std::unique_ptr<BearingModel>> meshes;
  for (std::size_t k = 0; k < job.curve.points.size(); ++k) {
    const LimitCurvePoint& pt = job.curve.points[k];
    FoldBar& bar = job.bars[k];
    try {
      coarse->set_curve_parameter(which, pt.p);
      coarse->set_load(pt.state.load);
      std::size_t level = 0;
      bar.estimate = crossing_sequence(*coarse, job.kind, {pt.state.load, pt.u}, settings.bracket_width,
                                       settings.load_end, settings.tolerance,
                                       [&](const Scene& next) -> BearingModel& {
                                         if (meshes.size() == level)
                                           meshes.push_back(coarse->on_mesh(next.mesh.radial_nodes,
                                                                           next.mesh.circumferential_nodes));
                                         BearingModel& fine = *meshes[level++];
                                         fine.set_curve_parameter(which, pt.p);
                                         return fine;
                                       },
                                       bar.why);
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      bar.why = e.what();
    }
  }
}

}  // namespace

void trace_job(const Scene& scene, CurveParameter which, const LimitCurveSettings& settings, LimitCurveJob& job) {
  const auto t0 = std::chrono::steady_clock::now();
  try {
    BearingModel model(scene);
    job.curve = trace_limit_curve(model, which, job.kind, job.from, job.to, job.start, settings);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    job.curve.ended = std::string("the curve could not be continued: ") + e.what();
  }
  if (settings.error_bars) bar_points(scene, which, settings, job);
  job.seconds = elapsed_ms(t0) / 1000.0;
}

void add_limit_curve(const LimitCurveJob& job, const Study& st, std::optional<double> member,
                     const std::string& label, double tolerance, StudyOutcome& out, const std::function<void(const std::string&)>& say) {
  const LimitCurve& curve = job.curve;
  std::vector<FoldCurveRow>& rows = out.own_part<DistressCurveOutcome>().rows;
  for (std::size_t k = 0; k < curve.points.size(); ++k) {
    const LimitCurvePoint& pt = curve.points[k];
    FoldCurveRow& row = rows.emplace_back();
    row.parameter = pt.p;
    row.fold = FoldKind::limit;
    row.limit = job.kind;
    row.state = pt.state;
    row.member = member;
    if (k < job.bars.size() && job.bars[k].estimate) put_bar(row, *job.bars[k].estimate);
  }
  const std::string line =
      curve.points.empty()
          ? fmt::format("limit curve{}: {} not traced from {}: {}", label, limit_name(job.kind), shown_parameter(st, job.from),
                        curve.ended)
          : fmt::format("limit curve{}: {} crossed from {:.2f} N at {} to {:.2f} N at {} ({} points){}", label,
                        limit_name(job.kind), curve.points.front().state.load, shown_parameter(st, curve.points.front().p),
                        curve.points.back().state.load, shown_parameter(st, curve.points.back().p), curve.points.size(),
                        curve.ended.empty() ? std::string() : "; ended " + curve.ended);
  std::string with_bars = line;
  std::optional<std::string> warning;
  if (!job.bars.empty()) {
    const std::string curve_name = fmt::format("limit curve{}: {}", label, limit_name(job.kind));
    BarsSummary bars = bars_summary(
        job.bars, tolerance, "points", [&](std::size_t k) { return shown_parameter(st, curve.points[k].p); },
        curve_name);
    with_bars += "; " + bars.phrase;
    warning = std::move(bars.warning);
  }
  say(fmt::format("[curve{}] {} [{} steady solves, {:.1f} s]", label, with_bars.substr(with_bars.find(':') + 2),
                  curve.solves, job.seconds));
  out.summary.push_back(with_bars);
  if (warning) out.summary.push_back(*warning);
}

}  // namespace twb
