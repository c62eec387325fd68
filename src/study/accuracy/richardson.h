// W_d's discretization error (issue: an error bar on every W_d). The fold is located
// again on the mesh refined by two in each direction (radial intervals and
// circumferential nodes doubled), where it needs no transients: the dynamics already
// proved it on the scene's mesh. Richardson extrapolation with the discretization's
// formal order p = 2 (docs/model.md: second-order finite volumes),
//
//     W_ext = W_fine + (W_fine − W_coarse)/(2^p − 1),
//
// and Roache's grid convergence index as the error bar,
//
//     error = F_s·|W_fine − W_coarse|/(2^p − 1),   F_s = 1.25.
//
// The bar covers the extrapolation for any observed order down to p ≈ 1.22 (the
// extrapolated value moves by |Δ|·(1/(2^p − 1) − 1/3), which reaches 1.25·|Δ|/3 there).
// F_s = 1.25 is Roache's factor where three grids confirm the order (3 for two grids
// alone): the three-grid study is the test's and docs/model.md's, not each W_d's.
// W_d's observed order on the paper's bearing is 1.5 (5/9/17 radial nodes) rising to 1.8
// (9/17/33): contact and cavitation boundaries cost it the full second order on coarse
// meshes. tests/study/richardson_test.cpp checks the order and the cover on three meshes.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "twb/results/distress_table.h"
#include "twb/scene/scene.h"
#include "solver/fold_location.h"
#include "study/searches/distress_search.h"
#include "study/accuracy/mesh_convergence.h"

namespace twb {

struct MeshErrorEstimate {
  double fine_fold = 0.0;     // N, the fold on the refined mesh (the finest of a sequence)
  double extrapolated = 0.0;  // N
  double error = 0.0;         // N, the error bar of the extrapolated value
  std::string fine_mesh;      // e.g. "17 x 132"
  // A sequence to a tolerance (mesh_convergence.h): the meshes solved on, the order they
  // show, and whether the bar meets the tolerance (and why not); empty without one.
  LoadConvergence convergence;
};

// The scene with its mesh refined by two in each direction, its grooves placed on it at
// their angles and a dam at its radius (the same grooves as BearingModel::on_mesh).
Scene refined_mesh(const Scene& scene);
// Its mesh as the run names it, e.g. "17 x 132".
std::string mesh_name(const Scene& scene);

// The extrapolation and its error bar from a value on a mesh and on the mesh refined by
// two (the formula above, with F_s = safety); fine_mesh left empty.
MeshErrorEstimate richardson_extrapolation(double coarse, double fine, double safety = 1.25);
// Roache's factor for two grids alone, whose order no third grid confirms: the states'
// quantities (a maximum over nodes, a least gap) converge less regularly than W_d, whose
// order three grids confirm (richardson_test.cpp). With it the bar is |fine − coarse|.
inline constexpr double kTwoGridSafety = 3.0;

// The estimate from a load's mesh sequence (mesh_convergence.h): the two-mesh bar of the
// formal order above where no tolerance is asked (tolerance 0), else mesh_converged's with
// how it was reached (the meshes, the order they show, whether the tolerance is met and
// why not). `finest` names the last mesh solved on.
MeshErrorEstimate sequence_estimate(const MeshSequence& sequence, double tolerance, const std::string& finest);

// The fold on the scene's mesh, as its search found it.
struct CoarseFold {
  double load = 0.0;  // N
  // The located fold and the model it lives on, when the search has them: the refined
  // fold is then located from it directly (interpolated onto the refined mesh, one Newton
  // on the minimally augmented system), and searched along the branch only where that
  // fails.
  const BearingModel* model = nullptr;
  const FoldPoint* point = nullptr;
};

// Where the refined mesh's fold comes from: a few Newton iterations from the coarse
// fold (on the paper's bearing, 9×66 → 17×132: about a third of the cost of continuing
// the refined branch from the light load). The located fold must be a largest load
// (fold curvature κ > 0, as the cool branch's end is) within 30 % of the coarse load;
// otherwise the refined branch is continued from the light load as before.
//
// From the fold on the scene's mesh at `speed`. The fold on the refined mesh is located
// from the coarse one (above) or searched from settings.load_start to settings.load_end.
// Empty, with the reason in `why`, when the refined mesh has no fold there.
std::optional<MeshErrorEstimate> richardson_estimate(const Scene& scene, double speed, const CoarseFold& coarse,
                                                     DistressSearchSettings settings, std::string& why,
                                                     const SearchProgress& progress = {});

// The fold on the mesh refined by two from the fold on the scene's mesh, as
// richardson_estimate finds it, with the refined model and its located fold (empty where
// a search of the refined branch found it without one) for the next mesh of a sequence.
struct RefinedFold {
  double load = 0.0;  // N
  std::unique_ptr<BearingModel> model;
  std::optional<FoldPoint> point;
};
std::optional<RefinedFold> refined_fold(const Scene& scene, double speed, const CoarseFold& coarse,
                                        DistressSearchSettings settings, std::string& why,
                                        const SearchProgress& progress = {});

// One step further along a mesh sequence: the fold on `fine` (the bearing on the next
// finer mesh) from the fold `at` on `coarse`, interpolated, then Newton on the minimally
// augmented system until a step moves the load by less than load_accuracy (N); checked
// as the first step is (a largest load within 30 % of the coarse one). Empty, with `why`.
std::optional<FoldPoint> fold_on_finer_mesh(const BearingModel& coarse, const FoldPoint& at, BearingModel& fine,
                                            double load_accuracy, std::string& why);

// A crossing one step further along a mesh sequence: `state` holds the crossing's load
// and state on `coarse`, and comes back with the crossing on `fine` as crossing_near
// leaves it (the last solve's load and state: a start for the next mesh). The refined
// crossing's load, or empty with `why`; as crossing_estimate below. Its first solve
// stands at `predicted` where given (> 0: the load the sequence expects on `fine`,
// next_mesh_value), else at the coarse crossing; `slope` holds the coarse crossing's
// dmargin/dW (0: none) and comes back with the refined one's.
std::optional<double> crossing_on_finer_mesh(const BearingModel& coarse, BearingModel& fine, LimitKind kind,
                                             std::pair<double, std::vector<double>>& state, double width,
                                             double load_end, std::string& why, double predicted, double& slope);

// A crossing along the mesh sequence (mesh_convergence.h): from its load and state on
// `coarse` (the scene's mesh) on the mesh refined by two, and with a tolerance on each
// finer mesh from the last one's crossing (crossing_on_finer_mesh) until its bar meets it,
// each located to the bracket width, or with a tolerance to a fifth of it where finer. `finer(next)` gives the bearing on the sequence's next mesh,
// standing where `coarse` stands, and keeps it while the sequence goes on. Empty, with
// `why`, where the first refinement fails; a later failure ends the sequence, said in its
// estimate's convergence.
using FinerBearing = std::function<BearingModel&(const Scene& next)>;
std::optional<MeshErrorEstimate> crossing_sequence(const BearingModel& coarse, LimitKind kind,
                                                   std::pair<double, std::vector<double>> state, double bracket_width,
                                                   double load_end, double tolerance, const FinerBearing& finer,
                                                   std::string& why);

// A failure criterion's crossing (failure_load.h) again on the refined mesh: the coarse
// crossing's state interpolated onto the refined mesh, Newton there at the coarse load,
// then the secant on the margin to the crossing (crossing_near), each solve only as far
// as the crossing's load needs (within about a tenth of the bracket width, as the coarse
// crossing is located; docs/physics.md section 8). `fine` is the coarse model on
// the refined mesh (BearingModel::on_mesh). Empty, with `why`, where Newton or the
// secant fails there.
std::optional<MeshErrorEstimate> crossing_estimate(const BearingModel& coarse, BearingModel& fine, LimitKind kind,
                                                   double load, std::span<const double> u, double width,
                                                   double load_end, std::string& why);

// The folds of a fold curve (study type distress_curve) again on the refined mesh, point
// after point along the curve: each from the last refined fold moved by the coarse
// curve's step (the coarse-to-fine difference changes little from point to point), the
// first from the coarse fold itself as above. Not for concurrent use; one per curve.
class RefinedFoldCurve {
 public:
  // coarse: the curve's model (its curve parameter and every other setting as the
  // curve's); first: the curve's first fold on it.
  RefinedFoldCurve(const BearingModel& coarse, CurveParameter which, const FoldPoint& first);
  // A chain that starts inside the curve: at its first fold's coarse state u, with a
  // null vector guess (any vector not orthogonal to the null vector there, e.g. another
  // fold's of the curve), coarse.
  RefinedFoldCurve(const BearingModel& coarse, CurveParameter which, std::span<const double> u,
                   std::span<const double> null_guess);

  // The estimate at the curve point (p, coarse load, coarse state u) whose fold is a
  // largest load (kind > 0, distress) or a smallest (kind < 0, recovery); empty, with the
  // reason in `why`, where Newton fails there or finds another kind of fold, or one
  // more than 30 % of the coarse load away (the next point then starts afresh).
  std::optional<MeshErrorEstimate> at(double p, double load, std::span<const double> u, int kind, std::string& why);
  const std::string& mesh() const { return mesh_; }  // e.g. "17 x 132"

  // The refined model, and the last point's refined fold (state, null vector, load): the
  // coarse model and first fold of a RefinedFoldCurve one mesh further. The fold is empty
  // where the last point had none.
  const BearingModel& fine_model() const { return *fine_; }
  std::span<const double> last_fold() const { return state_part(last_fine_); }
  std::span<const double> last_null_vector() const { return state_part(last_null_); }
  double last_fold_load() const { return last_fine_load_; }

 private:
  const BearingModel& coarse_;
  std::unique_ptr<BearingModel> fine_;
  CurveParameter which_;
  std::string mesh_;
  std::vector<double> first_null_;  // the first fold's null vector, coarse
  // The last point's coarse state and load and its refined fold, when it had one.
  std::vector<double> last_coarse_, last_fine_, last_null_;
  double last_coarse_load_ = 0.0, last_fine_load_ = 0.0;
  // A refined fold's vector as a state of the refined model (the bordered systems may
  // append their own unknowns).
  std::span<const double> state_part(const std::vector<double>& v) const {
    return std::span<const double>(v).first(std::min(v.size(), std::size_t(fine_->size())));
  }
};

}  // namespace twb
