#include "study/accuracy/mesh_convergence.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "study/accuracy/richardson.h"
#include "twb/error_family.h"

namespace twb {

namespace {

constexpr double kFormalOrder = 2.0;  // second-order finite volumes (docs/model.md)
constexpr double kThreeGridSafety = 1.25;  // Roache's factor where three grids show the order

}  // namespace

MeshConvergence mesh_converged(std::span<const double> values) {
  if (values.size() < 2) throw InternalError("mesh_converged: an estimate needs two meshes at least");
  const std::size_t n = values.size();
  const double finest = values[n - 1];
  const double last = finest - values[n - 2];
  MeshConvergence e;
  if (n == 2) {
    const double change = last / (std::pow(2.0, kFormalOrder) - 1.0);
    e.value = finest + change;
    e.error = kTwoGridSafety * std::abs(change);
    return e;
  }
  const double before = values[n - 2] - values[n - 3];
  if (before * last > 0.0 && std::abs(last) < std::abs(before)) {
    const double observed = std::log2(before / last);
    e.order = observed;
    const double change = last / (std::pow(2.0, std::min(observed, kFormalOrder)) - 1.0);
    e.value = finest + change;
    e.error = kThreeGridSafety * std::abs(change);
    return e;
  }
  // Oscillating or growing differences (or a last one of exactly nought after a step):
  // no asymptotic range is seen; the finest value, within the spread of the last steps.
  e.value = finest;
  e.error = std::max(std::abs(last), std::abs(before));
  return e;
}

double next_mesh_value(std::span<const double> values) {
  if (values.size() < 2) return values.empty() ? 0.0 : values.back();
  const double order = values.size() > 2 ? mesh_converged(values).order.value_or(kFormalOrder) : kFormalOrder;
  return values.back() + (values.back() - values[values.size() - 2]) / std::pow(2.0, order);
}

bool within_tolerance(const MeshConvergence& estimate, double tolerance) {
  return estimate.error <= tolerance * std::abs(estimate.value);
}

std::vector<Scene> refined_meshes(const Scene& scene) {
  std::vector<Scene> meshes{refined_mesh(scene)};
  while (int(meshes.size()) < scene.mesh.max_refinements) meshes.push_back(refined_mesh(meshes.back()));
  return meshes;
}

MeshSequence::MeshSequence(const Scene& scene, double scene_load)
    : mesh_(scene.mesh), meshes_(refined_meshes(scene)), loads_{scene_load} {}

void MeshSequence::add(double load) {
  if (!next_mesh()) throw InternalError("MeshSequence::add: no mesh left to solve on");
  loads_.push_back(load);
}

bool MeshSequence::wants_more(double tolerance) const {
  if (loads_.size() < 2) return true;
  return stopped_.empty() && !within_tolerance(estimate(), tolerance);
}

std::string MeshSequence::solved_meshes() const {
  std::string names = fmt::format("{}x{}", mesh_.radial_nodes, mesh_.circumferential_nodes);
  for (std::size_t k = 0; k + 1 < loads_.size(); ++k)
    names += fmt::format(" {}x{}", meshes_[k].mesh.radial_nodes, meshes_[k].mesh.circumferential_nodes);
  return names;
}

std::string MeshSequence::why_unmet(double tolerance) const {
  const MeshConvergence e = estimate();
  const std::string bar = fmt::format("{:.3g} %", 100.0 * e.error / std::abs(e.value));
  if (!stopped_.empty()) return fmt::format("its bar is {} (tolerance {:.2g} %): {}", bar, 100.0 * tolerance, stopped_);
  const Scene finer = refined_mesh(meshes_[loads_.size() - 2]);
  return fmt::format("its bar is {} (tolerance {:.2g} %) after mesh.max_refinements: {}; the next mesh, {} x {}, "
                     "is allowed by a larger mesh.max_refinements",
                     bar, 100.0 * tolerance, mesh_.max_refinements, finer.mesh.radial_nodes,
                     finer.mesh.circumferential_nodes);
}

}  // namespace twb
