// A failure load to a requested accuracy (study.tolerance; docs/physics.md section 8,
// "To a requested accuracy"): the load on a sequence of meshes, the scene's and each
// refined by two in both directions, and its mesh-converged estimate with an error bar.
//
// Two meshes alone confirm no order: the estimate is Richardson's with the formal order
// p = 2 and Roache's two-grid factor F_s = 3, so the bar is |Q1 − Q0|. From three on,
// the last three give the observed order
//
//     p = log2((Q1 − Q0)/(Q2 − Q1)),
//
// where the differences share their sign and fall (monotone convergence), and the
// estimate and Roache's grid convergence index with F_s = 1.25 (three grids):
//
//     Q* = Q2 + (Q2 − Q1)/(2^p − 1),   error = 1.25·|Q2 − Q1|/(2^p − 1),
//
// p capped at the formal order (an observed order above it, a chance of the data, would
// shrink the bar). Where the differences change sign or grow, no order is seen: the
// estimate is the finest value and the bar the larger of the last two differences.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "twb/scene/scene.h"

namespace twb {

struct MeshConvergence {
  double value = 0.0;           // the mesh-converged estimate
  double error = 0.0;           // its bar, in the value's unit (>= 0)
  std::optional<double> order;  // the observed order, where three meshes show one
};

// The estimate from values[0] on the scene's mesh, values[k] on it refined k times; at
// least two values.
MeshConvergence mesh_converged(std::span<const double> values);

// The value the next finer mesh should give, for its solve's start: the last plus the
// last difference shrunk by 2^p (p the observed order where three values show one, else
// the formal order); with one value, that value.
double next_mesh_value(std::span<const double> values);

// Whether the estimate's bar is within the relative tolerance of its value.
bool within_tolerance(const MeshConvergence& estimate, double tolerance);

// The meshes of the sequence as far as the scene allows (mesh.max_refinements): the
// scene's mesh refined by two, again and again. Each is the scene (grooves placed on it
// as refined_mesh does) with that mesh; the scene's own mesh is not among them.
std::vector<Scene> refined_meshes(const Scene& scene);

// One failure load along the sequence: its load on the scene's mesh, then on each finer
// mesh as the caller solves it, until its bar meets the tolerance, the limits allow no
// finer mesh, or a mesh's solve fails (stop).
class MeshSequence {
 public:
  MeshSequence(const Scene& scene, double scene_load);
  // The next mesh to solve on, or none past the limits.
  const Scene* next_mesh() const { return loads_.size() <= meshes_.size() ? &meshes_[loads_.size() - 1] : nullptr; }
  void add(double load);  // the load on next_mesh()
  void stop(std::string why) { stopped_ = std::move(why); }
  // Whether another mesh is wanted: not yet two loads, or the bar is not yet within the
  // tolerance and nothing stopped the sequence.
  bool wants_more(double tolerance) const;
  const std::vector<double>& loads() const { return loads_; }
  // The estimate (mesh_converged) from the loads so far, at least two.
  MeshConvergence estimate() const { return mesh_converged(loads_); }
  // The meshes solved on, "9x66 17x132 33x264".
  std::string solved_meshes() const;
  // Why the sequence ended short of the tolerance: a failed solve, or the limits.
  std::string why_unmet(double tolerance) const;

 private:
  MeshSettings mesh_;  // the scene's
  std::vector<Scene> meshes_;  // refined_meshes(scene)
  std::vector<double> loads_;
  std::string stopped_;
};

}  // namespace twb
