#include "study/searches/followed_map.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "study/uncertainty/failure_at_inputs.h"
#include "study/searches/failure_load.h"
#include "study/parallel/parallel.h"
#include "solver/sparse_lu.h"
#include "study/study_support.h"
#include "twb/error_family.h"
#include "twb/results/run_axes.h"

namespace twb {

namespace {

using Clock = std::chrono::steady_clock;

// The row of a followed point: W_fail and its criterion, W_d where a fold is settled,
// each settled criterion's load; a searched point's own row.
DistressRow followed_row(const FailureLoadAtInputs::Followed& p, double speed, const std::vector<double>& parameters,
                         const std::string& from, const DistressSearchSettings& settings) {
  if (p.search_row) {
    DistressRow row = *p.search_row;
    row.speed = speed;
    row.parameters = parameters;
    row.method = "searched: " + row.method;
    return row;
  }
  DistressRow row;
  row.speed = speed;
  row.parameters = parameters;
  if (p.fold) {
    row.distress_load = row.fold_load = p.fold;
    row.verdict = DistressVerdict::fold_only;
  } else {
    row.verdict = DistressVerdict::undecided;
  }
  for (const auto& [kind, load] : p.crossings)
    if (const std::optional<std::size_t> c = criterion_index(kind)) row.criterion_loads[*c] = load;
  if (std::isfinite(p.failure.load)) {
    row.failure_load = p.failure.load;
    row.criterion = FailureCriterion::thermo_viscous_distress();
    for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c)
      if (row.criterion_loads[c] == p.failure.load) row.criterion = FailureCriterion::crossing(kFailureCriteria[c]);
  }
  row.method = fmt::format("followed by Newton from {}{}", from,
                           p.fold ? fmt::format(": fold at {:.6g} N (not proven by transients)", *p.fold) : "");
  row.failure = failure_sentence(row, settings.load_end);
  return row;
}

// The combination's label for a row's method: its axes and speed.
std::string point_label(const std::vector<std::string>& columns, const std::vector<double>& x, bool in_rpm) {
  std::string out;
  for (std::size_t k = 0; k < columns.size(); ++k) out += fmt::format("{} = {:.6g}, ", columns[k], x[k]);
  return out + speed_text(x.back(), in_rpm);
}

}  // namespace

void run_followed_map(BearingModel& base, const DistressSearchSettings& settings, StudyOutcome& out,
                      const ProgressReport& progress, const Running& how) {
  const Scene& scene = base.scene();
  const std::vector<MapAxis>& axes = std::get<DistressMapSettings>(scene.study.settings).axes;
  const std::vector<Variant> variants = parameter_variants(scene, out.parameter_columns);
  const std::vector<double> speeds = study_speeds(base);
  // The inputs x: each axis's path (the scene reader refused axes that have none), then
  // the speed; the point's dimensions in the same order, the speed turning fastest.
  std::vector<std::string> paths;
  for (const MapAxis& axis : axes) {
    paths.push_back(parameter_path(axis));
    if (paths.back().empty()) throw InternalError("run_followed_map: an axis without a single input");
  }
  paths.push_back("operating.speed");
  std::vector<std::size_t> sizes;
  for (const MapAxis& axis : axes) sizes.push_back(axis.values.size());
  sizes.push_back(speeds.size());
  const std::size_t dims = sizes.size(), total = variants.size() * speeds.size();
  auto x_of = [&](std::size_t flat) {
    std::vector<double> x = variants[flat / speeds.size()].parameters;
    x.push_back(speeds[flat % speeds.size()]);
    return x;
  };
  // (The inputs' scales choose a nearest anchor, which follow() never does.)
  FailureLoadAtInputs failure(scene, paths, std::vector<double>(dims, 1.0), settings, 1);

  const auto t0 = Clock::now();
  std::vector<std::optional<FailureLoadAtInputs::Followed>> at(total);
  std::vector<std::string> from(total), why(total);
  std::mutex lock;
  std::size_t done = 0;
  // Point `flat` from point `parent` (none: a search).
  auto settle = [&](std::size_t flat, std::optional<std::size_t> parent) {
    if (how.stop && how.stop->load()) return;  // left unsettled: no row
    const SparseLu::Counts before = SparseLu::thread_counts();  // this thread's, so this point's
    const FailureLoadAtInputs::Followed* start = parent && at[*parent] ? &*at[*parent] : nullptr;
    try {
      at[flat] = failure.follow(start, x_of(flat), why[flat]);
    } catch (const InternalError&) {
      throw;  // a bug: no row may hide it
    } catch (const std::exception& e) {
      // One combination that cannot be settled must not lose the map's other rows.
      why[flat] = e.what();
    }
    if (parent) from[flat] = point_label(out.parameter_columns, x_of(*parent), scene.study.speeds_in_rpm);
    const std::lock_guard<std::mutex> hold(lock);
    out.timings.klu_factorizations += SparseLu::thread_counts().factored_since(before);
    ++done;
    if (progress && (done % 50 == 0 || done == total))
      progress(fmt::format("  followed {} of {} combinations ({} searched) [{:.1f} s]", done, total,
                           failure.searches(), elapsed_ms(t0) / 1000.0));
  };
  // The flat index of a point given by its indices (the last dimension fastest).
  auto flat_of = [&](const std::vector<std::size_t>& index) {
    std::size_t flat = 0;
    for (std::size_t d = 0; d < dims; ++d) flat = flat * sizes[d] + index[d];
    return flat;
  };
  settle(0, std::nullopt);
  // Level d: from every point settled so far (its dimensions ≥ d at their first values),
  // a chain along dimension d; the chains of one level run at once.
  std::vector<std::vector<std::size_t>> roots{std::vector<std::size_t>(dims, 0)};
  for (std::size_t d = 0; d < dims; ++d) {
    run_in_parallel(roots.size(), how.threads, [&](std::size_t r) {
      std::vector<std::size_t> index = roots[r];
      for (std::size_t i = 1; i < sizes[d]; ++i) {
        const std::size_t parent = flat_of(index);
        index[d] = i;
        settle(flat_of(index), parent);
      }
    });
    std::vector<std::vector<std::size_t>> next;
    for (const std::vector<std::size_t>& root : roots)
      for (std::size_t i = 0; i < sizes[d]; ++i) {
        next.push_back(root);
        next.back()[d] = i;
      }
    roots = std::move(next);
  }

  const bool stopped = how.stop && how.stop->load();
  for (std::size_t flat = 0; flat < total; ++flat) {
    const std::vector<double> x = x_of(flat);
    const std::vector<double>& parameters = variants[flat / speeds.size()].parameters;
    if (!at[flat] && stopped && why[flat].empty()) continue;  // not reached before the stop
    if (!at[flat]) {
      DistressRow row;
      row.speed = x.back();
      row.parameters = parameters;
      row.verdict = DistressVerdict::solver_failure;
      row.method = "solver failure: " + why[flat];
      row.failure = failure_sentence(row, settings.load_end);
      out.message += (out.message.empty() ? "" : "; ") + fmt::format("{}: {}", point_label(out.parameter_columns, x, scene.study.speeds_in_rpm), why[flat]);
      out.distress.push_back(std::move(row));
      continue;
    }
    out.distress.push_back(followed_row(*at[flat], x.back(), parameters, from[flat], settings));
  }
  out.summary.push_back(fmt::format("followed map: {} combinations, {} failure searches, {:.1f} s", total,
                                    failure.searches(), elapsed_ms(t0) / 1000.0));
  if (stopped) {
    out.stopped = true;
    out.message += (out.message.empty() ? "" : "; ") +
                   std::string("stopped before the study's end: combinations are missing");
  }
}

}  // namespace twb
