#include "study/accuracy/fold_curve_bars.h"

#include <chrono>
#include <algorithm>
#include <exception>

#include <fmt/format.h>

#include "study/accuracy/mesh_convergence.h"
#include "study/study_support.h"
#include "twb/error_family.h"

namespace twb {

void put_bar(FoldCurveRow& row, const MeshErrorEstimate& e) {
  row.fine_load = e.fine_fold;
  row.extrapolated_load = e.extrapolated;
  row.discretization_error = e.error;
  row.convergence = e.convergence;
}

BarsSummary bars_summary(std::span<const FoldBar> bars, double tolerance, const std::string& points,
                         const std::function<std::string(std::size_t)>& where, const std::string& curve) {
  std::size_t with_bar = 0, met = 0;
  std::string last_why, mesh, meshes;
  std::optional<double> low_order, high_order;
  std::optional<std::size_t> first_unmet;
  for (std::size_t k = 0; k < bars.size(); ++k) {
    const std::optional<MeshErrorEstimate>& e = bars[k].estimate;
    if (!e) {
      last_why = bars[k].why;
      continue;
    }
    ++with_bar;
    if (mesh.empty()) mesh = e->fine_mesh;
    const LoadConvergence& c = e->convergence;
    if (c.meshes.size() > meshes.size()) meshes = c.meshes;
    if (c.order) {
      low_order = std::min(low_order.value_or(*c.order), *c.order);
      high_order = std::max(high_order.value_or(*c.order), *c.order);
    }
    if (c.tolerance_met && *c.tolerance_met)
      ++met;
    else if (c.tolerance_met && !first_unmet)
      first_unmet = k;
  }
  if (with_bar == 0) return {"no error bars: " + last_why, std::nullopt};
  const std::string missing = with_bar < bars.size() ? " (the last missing: " + last_why + ")" : std::string();
  if (tolerance <= 0.0)
    return {fmt::format("error bars from the {} mesh at {} of {} {}{}", mesh, with_bar, bars.size(), points, missing),
            std::nullopt};
  const std::string orders =
      !low_order ? std::string()
      : *low_order == *high_order
          ? fmt::format(", observed order {:.2f}", *low_order)
          : fmt::format(", observed orders {:.2f} to {:.2f}", *low_order, *high_order);
  BarsSummary out{fmt::format("mesh-converged at {} of {} {}, within {:.3g} % at {} (meshes {}{}){}", with_bar,
                              bars.size(), points, 100.0 * tolerance, met, meshes, orders, missing),
                  std::nullopt};
  if (first_unmet)
    out.warning = fmt::format("warning: {}: not within the tolerance at {} of the {}; the first at {}: {}", curve,
                              with_bar - met, points, where(*first_unmet),
                              bars[*first_unmet].estimate->convergence.why_unmet);
  return out;
}

FoldCurveBars::FoldCurveBars(const Scene& scene, CurveParameter which, const FoldPoint& first,
                             std::size_t most_points, double tolerance, std::function<void(const std::string&)> say)
    : scene_(scene),
      which_(which),
      first_(first),
      tolerance_(tolerance),
      say_(std::move(say)),
      bars_(most_points) {}

std::string FoldCurveBars::mesh() const {
  const std::lock_guard<std::mutex> hold(mesh_lock_);
  return mesh_;
}

std::optional<MeshErrorEstimate> FoldCurveBars::estimate(std::vector<std::unique_ptr<RefinedFoldCurve>>& levels,
                                                         const FoldCurvePoint& pt, int kind,
                                                         std::string& why) const {
  const std::optional<MeshErrorEstimate> first = levels.front()->at(pt.p, pt.lambda, pt.u, kind, why);
  if (!first) return std::nullopt;
  MeshSequence sequence(scene_, pt.lambda);
  sequence.add(first->fine_fold);
  std::string finest = levels.front()->mesh();
  if (tolerance_ <= 0.0) return sequence_estimate(sequence, tolerance_, finest);
  // Each level's coarse model is the level below's refined one, which its `at` has just
  // set to this point's parameter; its fold there is this level's start.
  for (std::size_t level = 1; sequence.wants_more(tolerance_) && sequence.next_mesh(); ++level) {
    const RefinedFoldCurve& below = *levels[level - 1];
    std::string step_why;
    try {
      if (levels.size() == level)
        levels.push_back(std::make_unique<RefinedFoldCurve>(below.fine_model(), which_, below.last_fold(),
                                                            below.last_null_vector()));
      const std::optional<MeshErrorEstimate> finer =
          levels[level]->at(pt.p, below.last_fold_load(), below.last_fold(), kind, step_why);
      if (finer) {
        sequence.add(finer->fine_fold);
        finest = levels[level]->mesh();
        continue;
      }
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      step_why = e.what();
    }
    sequence.stop(fmt::format("the fold on {} from the one on {} failed: {}", mesh_name(*sequence.next_mesh()),
                              finest, step_why));
    break;
  }
  return sequence_estimate(sequence, tolerance_, finest);
}

void FoldCurveBars::run_chain(std::size_t chain, FoldCurveFeed& feed) {
  const std::size_t a = chain * kChainPoints, b = std::min(a + kChainPoints, bars_.size());
  std::optional<FoldCurveFeed::Entry> at = feed.wait_for(a);
  if (!at) return;
  const auto t0 = std::chrono::steady_clock::now();
  BearingModel coarse(scene_);
  coarse.set_curve_parameter(which_, at->first.p);
  coarse.set_load(at->first.lambda);
  // The chain's refined curves: [0] on the mesh refined by two, [1] by four, and so on,
  // each built when a fold first needs it.
  std::vector<std::unique_ptr<RefinedFoldCurve>> levels;
  std::string unbuilt;
  try {
    levels.push_back(chain == 0 ? std::make_unique<RefinedFoldCurve>(coarse, which_, first_)
                                : std::make_unique<RefinedFoldCurve>(coarse, which_, at->first.u,
                                                                     first_.null_vector));
    const std::lock_guard<std::mutex> hold(mesh_lock_);
    mesh_ = levels.front()->mesh();
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    unbuilt = std::string("the refined mesh could not be built: ") + e.what();
  }
  std::size_t k = a;
  for (; k < b; ++k) {
    if (k > a && !(at = feed.wait_for(k))) break;
    if (levels.empty()) {
      bars_[k].why = unbuilt;
      continue;
    }
    const FoldCurvePoint& pt = at->first;
    coarse.set_curve_parameter(which_, pt.p);
    coarse.set_load(pt.lambda);
    try {
      bars_[k].estimate = estimate(levels, pt, at->second, bars_[k].why);
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& failure) {
      bars_[k].why = failure.what();
    }
  }
  if (say_ && k > a)
    say_(fmt::format("error bars of the folds {} to {} on up to {} meshes [{:.1f} s]", a + 1, k,
                     1 + levels.size(), elapsed_ms(t0) / 1000.0));
}

}  // namespace twb
