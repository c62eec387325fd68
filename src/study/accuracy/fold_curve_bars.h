// W_fold's error bars along a fold curve (study type distress_curve; docs/physics.md
// section 8, "To a requested accuracy"). Every fold of the curve again on the mesh
// refined by two (RefinedFoldCurve, richardson.h), in chains of kChainPoints consecutive
// points that follow the curve as it is traced: each fold from the last refined fold of
// its chain. With a tolerance (study.tolerance), a fold whose bar misses it is located
// again on each finer mesh in turn, by a RefinedFoldCurve one level further whose coarse
// model is the level below's refined one, until its bar meets the tolerance or the
// scene's mesh limits (mesh.max_refinements) end its sequence (mesh_convergence.h).
// The cut into chains is the same for any thread count, so are the bars.
#pragma once

#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "solver/fold_location.h"
#include "study/searches/fold_curve_feed.h"
#include "study/accuracy/richardson.h"
#include "twb/results/fold_curve_table.h"
#include "twb/scene/scene.h"

namespace twb {

// One fold's bar, or why it has none.
struct FoldBar {
  std::optional<MeshErrorEstimate> estimate;
  std::string why;
};

// A curve row's bar columns from its estimate.
void put_bar(FoldCurveRow& row, const MeshErrorEstimate& e);

// What the bars of a curve's points came to: a phrase ("error bars from the 17 x 132
// mesh at 24 of 24 folds"; with a tolerance "mesh-converged at 24 of 24 folds, within
// 1 % at 24 (meshes 9x66 17x132 33x264, observed orders 1.69 to 1.83)"; "no error bars:
// <why>" where none has one) and, where some miss the tolerance, a warning naming how
// many and the first one's reason. `points` names them ("folds"), `where(k)` says where
// point k lies, `curve` names the curve in the warning ("fold curve").
struct BarsSummary {
  std::string phrase;
  std::optional<std::string> warning;
};
BarsSummary bars_summary(std::span<const FoldBar> bars, double tolerance, const std::string& points,
                         const std::function<std::string(std::size_t)>& where, const std::string& curve);

class FoldCurveBars {
 public:
  static constexpr std::size_t kChainPoints = 6;

  // scene: the curve's scene as it stands before the curve is traced (the trace moves its
  // model's curve parameter while the chains build theirs); first: the curve's first fold
  // on the scene's mesh; most_points: the most points the curve may have; tolerance: the
  // study's (relative; 0: none). `say` reports each chain's end (may be empty).
  FoldCurveBars(const Scene& scene, CurveParameter which, const FoldPoint& first, std::size_t most_points,
                double tolerance, std::function<void(const std::string&)> say);

  std::size_t chains() const { return (bars_.size() + kChainPoints - 1) / kChainPoints; }
  // The bars of chain `chain`'s points, taken from the feed as the trace adds them. Distinct
  // chains may run on distinct threads at once.
  void run_chain(std::size_t chain, FoldCurveFeed& feed);

  const FoldBar& operator[](std::size_t k) const { return bars_[k]; }
  // The first `count` points' bars (the points the curve has).
  std::span<const FoldBar> first(std::size_t count) const { return std::span<const FoldBar>(bars_).first(count); }
  // The mesh refined by two, e.g. "17 x 132"; empty where no chain could build it.
  std::string mesh() const;

 private:
  // Point pt's estimate: on the level-one refined mesh, then with a tolerance further
  // along the sequence; `levels` holds the chain's refined curves, built as needed.
  std::optional<MeshErrorEstimate> estimate(std::vector<std::unique_ptr<RefinedFoldCurve>>& levels,
                                            const FoldCurvePoint& pt, int kind, std::string& why) const;

  const Scene scene_;
  const CurveParameter which_;
  const FoldPoint first_;
  const double tolerance_;  // relative; 0: the two-mesh bar of the formal order alone
  std::function<void(const std::string&)> say_;
  std::vector<FoldBar> bars_;
  mutable std::mutex mesh_lock_;
  std::string mesh_;
};

}  // namespace twb
