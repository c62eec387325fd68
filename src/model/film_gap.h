// A film's gap at its nodes (docs/physics.md section 1): the rigid plane, plus the thermal
// shape δ at the nodes where the faces deform, plus the face's relief g on a grooved or
// shaped face (face_relief.h). Every reader of a node's gap (the heat paths, the reported
// fields, the least gap, the film at a point) reads it here, at one state, so that a new
// part of the gap changes this one place.
//
// The sums keep the order each reader had before they met here (plane, then δ, then the
// relief; a node's mean relief summed before it is added), so that results stay
// bit-identical. The plane is Film::node_gap's, summed in the physics' order.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "model/film.h"
#include "model/sparse_assembly.h"

namespace twb {

class BearingModel;

class NodeGaps {
 public:
  // The film's node gaps at state u (its rigid position and, with thermal deformation,
  // its node shapes).
  NodeGaps(const BearingModel& model, std::span<const double> u, const Film& film);

  const Film& film() const { return *film_; }
  // Plane + δ at node n, whose load-frame position is (x, y): no relief.
  double smooth(int n, double x, double y) const { return film_->node_gap(q_, x, y) + shape(n); }
  // The same at grid node (i, j), at its polar position.
  double smooth(int i, int j) const;
  // The parts of node (i, j)'s control volume (one, with no relief, on a flat face).
  FaceRelief::NodeParts parts(int i, int j) const;
  // The node's gap as a field reports it: smooth plus its control volume's mean relief.
  double mean(int i, int j) const;
  // The least gap over the film: of the nodes (each with its least side's relief) and, on
  // a tilted plane, of the rim's point where the plane is least (δ interpolated there).
  double least() const;

  // δ at node n (nought without thermal deformation), and all of them (empty without).
  double shape(int n) const { return delta_.empty() ? 0.0 : delta_[std::size_t(n)]; }
  const std::vector<double>& shapes() const { return delta_; }
  // ∂h/∂u at a node: the plane's slopes in the rigid unknowns (Film::gap_gradient) and
  // δ's form in the shape's unknowns (empty without thermal deformation).
  std::array<double, 3> rigid_slope(double x, double y) const { return film_->gap_gradient(x, y); }
  const LinearForm& shape_form(int n) const;

 private:
  const BearingModel* model_;
  const Film* film_;
  RigidPosition q_;
  std::vector<double> delta_;
};

}  // namespace twb
