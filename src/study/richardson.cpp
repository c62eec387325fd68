#include "richardson.h"

#include <cmath>

#include <fmt/format.h>

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

std::optional<MeshErrorEstimate> richardson_estimate(const Scene& scene, double speed, double coarse_fold,
                                                     DistressSearchSettings settings, std::string& why,
                                                     const SearchProgress& progress) {
  const Scene fine_scene = refined_mesh(scene);
  BearingModel fine(fine_scene);
  fine.set_speed(speed);
  settings.fold_only = true;
  settings.grid.clear();
  settings.continue_past_distress = false;
  const std::string mesh = fmt::format("{} x {}", fine_scene.mesh.radial_nodes, fine_scene.mesh.circumferential_nodes);
  const DistressSearch found =
      search_distress(fine, settings, progress ? [&](const std::string& s) { progress("  [" + mesh + "]" + s); }
                                               : SearchProgress{});
  if (!found.row.fold_load) {
    why = fmt::format("no fold on the refined mesh ({} x {}): {}", fine_scene.mesh.radial_nodes,
                      fine_scene.mesh.circumferential_nodes, found.message.empty() ? found.row.method : found.message);
    return std::nullopt;
  }
  MeshErrorEstimate e;
  e.fine_fold = *found.row.fold_load;
  const double change = (e.fine_fold - coarse_fold) / (std::pow(2.0, formal_order) - 1.0);
  e.extrapolated = e.fine_fold + change;
  e.error = safety_factor * std::abs(change);
  e.fine_mesh = fmt::format("{} x {}", fine_scene.mesh.radial_nodes, fine_scene.mesh.circumferential_nodes);
  return e;
}

}  // namespace twb
