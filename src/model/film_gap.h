// A film's gap at a state (docs/physics.md section 1): the rigid plane, plus the shape δ
// the effects' parts of the gap give at the nodes (gap_contribution.h: thermal
// deformation's, a worn depth, …; interpolated bilinearly inside a cell, linearly along a
// face), plus the face's relief g on a grooved or shaped face (face_relief.h), which is
// fixed geometry resolved within a cell. Every kernel reads the gap here — at a node (the
// heat paths, the reported fields, the squeeze, the least gap), across a Reynolds face
// (the flows), on a cell's quadrature points (the loads) and at any point (the film at a
// point) — so that a new part of the gap changes none of them.
//
// The plane is summed two ways, equal to the last digit or two: as GapPlane::at (faces,
// cells, the squeeze) and in the physics' order, Film::node_gap (the heat paths, the
// fields, the least gap, a point); each reader keeps the one its results were computed
// with, so that shipped results stay bit-identical. The sums keep the order plane, then
// δ, then the relief (a node's mean relief summed before it is added).
#pragma once

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "model/film.h"
#include "model/reynolds_operator.h"
#include "model/sparse_assembly.h"

namespace twb {

class BearingModel;

// Least and greatest gap over a cell.
struct GapRange { double least = 0.0, greatest = 0.0; };

// The gap plane over the polar cells [r0, r1] × [t0, t1]: linear along rays, so its
// least and greatest values are at a corner or on an arc where the direction
// (cos θ, sin θ) is opposite to (a, b) (least) or along it (greatest). Those two
// directions are the plane's, the same for every cell: their angles are found once.
class PlaneOverCells {
 public:
  explicit PlaneOverCells(const GapPlane& plane);
  GapRange range(double r0, double r1, double t0, double t1, double c0, double s0, double c1, double s1) const;

 private:
  double c_, a_, b_;
  bool tilted_;
  double down_, up_;
};

// What a Reynolds face's flux reads of the gap at its midpoint: the smooth gap (plane
// and the mean of its nodes' shapes) and, on a relief's edge, the relief on either
// half, with the outer (after) half's share.
struct FaceGap {
  double smooth = 0.0;
  FaceRelief::Halves relief{0.0, 0.0};
  double outer_share = 0.5;
};

// The gap over cell (i, j) beyond its plane: the shape at its corners (i, j), (i+1, j),
// (i, j+1), (i+1, j+1), bilinear between, and the relief on its lines j and j+1, linear
// between; with the range of the whole gap over the cell.
struct CellGap {
  bool shaped = false, relief = false;
  std::array<double, 4> shape{};
  double relief_start = 0.0, relief_end = 0.0;
  GapRange range;
  double shape_at(double s, double t) const {
    return (1 - s) * (1 - t) * shape[0] + s * (1 - t) * shape[1] + (1 - s) * t * shape[2] + s * t * shape[3];
  }
  double relief_at(double t) const { return relief_start + t * (relief_end - relief_start); }
};

class FilmGap {
 public:
  // The film's gap at state u (its rigid position and the parts' unknowns).
  FilmGap(const BearingModel& model, std::span<const double> u, const Film& film);

  const Film& film() const { return *film_; }
  const GapPlane& plane() const { return plane_; }

  // At the nodes.
  // Plane + δ at node n, whose load-frame position is (x, y): no relief.
  double smooth(int n, double x, double y) const { return film_->node_gap(q_, x, y) + shape(n); }
  // The same at grid node (i, j), at its polar position.
  double smooth(int i, int j) const;
  // The same with the plane summed as GapPlane::at (the squeeze's).
  double smooth_on_plane(int n, double x, double y) const { return plane_.at(x, y) + shape(n); }
  // The parts of node (i, j)'s control volume (one, with no relief, on a flat face).
  FaceRelief::NodeParts parts(int i, int j) const;
  // The node's gap as a field reports it: smooth plus its control volume's mean relief.
  double mean(int i, int j) const;
  // The least gap over the film: of the nodes (each with its least side's relief) and, on
  // a tilted plane, of the rim's point where the plane is least (δ interpolated there).
  double least() const;

  // Across a Reynolds face between nodes na and nb, at its midpoint (x, y).
  FaceGap across(const ReynoldsFace& f, int na, int nb, double x, double y) const;

  // Over cell (i, j) with its corner nodes, its range widened from the plane's over it.
  CellGap cell(int i, int j, const std::array<int, 4>& corner_nodes, GapRange plane_range) const;
  // At a point of a cell: local (s, t), load-frame (x, y).
  double at(const CellGap& c, double s, double t, double x, double y) const {
    double h = plane_.at(x, y);
    if (c.shaped) h += c.shape_at(s, t);
    if (c.relief) h += c.relief_at(t);
    return h;
  }

  // At any point (r, θ) of the film, in cell (i, j) at local (s, t).
  double at_point(double r, double theta, int i, int j, double s, double t) const;

  // δ at node n (nought without a shape), and all of them (empty without).
  double shape(int n) const { return delta_.empty() ? 0.0 : delta_[std::size_t(n)]; }
  bool shaped() const { return !delta_.empty(); }
  const std::vector<double>& shapes() const { return delta_; }
  // ∂h/∂u at a node: the plane's slopes in the rigid unknowns (Film::gap_gradient) and
  // δ's form in the parts' unknowns (empty without a shape).
  std::array<double, 3> rigid_slope(double x, double y) const { return film_->gap_gradient(x, y); }
  const LinearForm& shape_form(int n) const;

 private:
  const BearingModel* model_;
  const Film* film_;
  RigidPosition q_;
  GapPlane plane_;
  std::vector<double> delta_;
};

}  // namespace twb
