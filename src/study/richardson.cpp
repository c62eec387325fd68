#include "richardson.h"

#include <cmath>

#include <fmt/format.h>

#include "study/study_support.h"

namespace twb {

namespace {

constexpr double formal_order = 2.0;
constexpr double safety_factor = 1.25;  // Roache's F_s

}  // namespace

Scene refined_mesh(const Scene& scene) {
  Scene fine = scene;
  fine.mesh.radial_nodes = 2 * (scene.mesh.radial_nodes - 1) + 1;
  fine.mesh.circumferential_nodes = 2 * scene.mesh.circumferential_nodes;
  return fine;
}

namespace {

// The coarse fold moved onto the refined model: its state, and its null vector as the
// difference of two interpolated states (the interpolation is linear in the state, and the
// edge values cancel).
struct MovedFold {
  std::vector<double> u, null_vector;
};

MovedFold moved_fold(const BearingModel& fine, const BearingModel& coarse, const FoldPoint& fold) {
  MovedFold moved;
  moved.u = fine.interpolated_from(coarse, fold.u);
  std::vector<double> shifted = fold.u;
  for (std::size_t k = 0; k < shifted.size(); ++k) shifted[k] += fold.null_vector[k];
  moved.null_vector = fine.interpolated_from(coarse, shifted);
  for (std::size_t k = 0; k < moved.u.size(); ++k) moved.null_vector[k] -= moved.u[k];
  return moved;
}

// The refined fold from the coarse one; empty with the reason in `why` when Newton fails
// or finds another kind of fold, or one too far away to be the same.
std::optional<double> fold_from_coarse(BearingModel& fine, const CoarseFold& coarse, std::string& why) {
  const MovedFold moved = moved_fold(fine, *coarse.model, *coarse.point);
  const FoldPoint fold =
      locate_fold_near(fine, moved.u, coarse.load, moved.null_vector, newton_settings(fine.scene()));
  if (fold.u.empty()) {
    why = fold.message;
    return std::nullopt;
  }
  if (!(fold.curvature > 0.0)) {
    why = fmt::format("the fold found at {:.6g} N is not a largest load (curvature {:.3g})", fold.lambda,
                      fold.curvature);
    return std::nullopt;
  }
  if (!(std::abs(fold.lambda - coarse.load) <= 0.5 * coarse.load)) {
    why = fmt::format("the fold found at {:.6g} N is too far from the coarse fold at {:.6g} N", fold.lambda,
                      coarse.load);
    return std::nullopt;
  }
  return fold.lambda;
}

}  // namespace

std::optional<MeshErrorEstimate> richardson_estimate(const Scene& scene, double speed, const CoarseFold& coarse,
                                                     DistressSearchSettings settings, std::string& why,
                                                     const SearchProgress& progress) {
  const Scene fine_scene = refined_mesh(scene);
  BearingModel fine(fine_scene);
  fine.set_speed(speed);
  const std::string mesh = fmt::format("{} x {}", fine_scene.mesh.radial_nodes, fine_scene.mesh.circumferential_nodes);
  const auto say = [&](const std::string& s) {
    if (progress) progress("  [" + mesh + "]" + s);
  };
  std::optional<double> fine_fold;
  if (coarse.model && coarse.point) {
    std::string direct_why;
    fine_fold = fold_from_coarse(fine, coarse, direct_why);
    if (fine_fold)
      say(fmt::format("  the fold from the coarse mesh's: {:.2f} N", *fine_fold));
    else
      say("  the fold from the coarse mesh's failed (" + direct_why + "); continuing the branch instead");
  }
  if (!fine_fold) {
    settings.fold_only = true;
    settings.grid.clear();
    settings.continue_past_distress = false;
    const DistressSearch found = search_distress(fine, settings, progress ? SearchProgress(say) : SearchProgress{});
    if (!found.row.fold_load) {
      why = fmt::format("no fold on the refined mesh ({}): {}", mesh,
                        found.message.empty() ? found.row.method : found.message);
      return std::nullopt;
    }
    fine_fold = *found.row.fold_load;
  }
  MeshErrorEstimate e;
  e.fine_fold = *fine_fold;
  const double change = (e.fine_fold - coarse.load) / (std::pow(2.0, formal_order) - 1.0);
  e.extrapolated = e.fine_fold + change;
  e.error = safety_factor * std::abs(change);
  e.fine_mesh = mesh;
  return e;
}

}  // namespace twb
