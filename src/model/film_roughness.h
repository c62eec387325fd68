// A film's roughness at a state (docs/physics.md sections 3, 4 and 20): each face's Rq,
// the scene's, or on the sliding film of a washer whose faces run in, each node's from
// its worn depth ([W5]-[W6], WearEffect::roughness). Every kernel that reads σ (the flow
// factors, the average gap, the shear flow's weight, the summits in contact) reads it
// here: at a node, across a Reynolds face (the mean of its two nodes' Rqs, as the gap's
// shape) and at a point of a cell (bilinear in its corners'), with the slopes of σ and of
// the shear term ψ = σ·w = (σ_turn² − σ_rest²)/σ (eq [3]) in each face's Rq there.
//
// A face's Rq at node n depends on one unknown, its depth there (the face at rest's at
// every node, the turning face's at every radial node): a kernel's slope in it is its
// slope in the Rq times dRq/dd, in the depth's column, which the gap's worn part already
// puts in the kernel's rows. Without running-in the film keeps Film::sigma and
// Film::shear_weight, and the kernels their paths.
#pragma once

#include <array>
#include <span>
#include <utility>
#include <vector>

#include "model/film.h"
#include "model/sparse_assembly.h"
#include "physics/value_slope.h"

namespace twb {

class BearingModel;

// σ and ψ from the faces' Rqs at a point, with their slopes in each.
struct PointRoughness {
  double sigma = 0.0, shear = 0.0;
  double sigma_by_rest = 0.0, sigma_by_turn = 0.0, shear_by_rest = 0.0, shear_by_turn = 0.0;
  static PointRoughness of(double rest, double turn);
};

class FilmRoughness {
 public:
  FilmRoughness(const BearingModel& model, std::span<const double> u, const Film& film);

  // Whether σ varies over the film (its faces run in); else every point has the film's.
  bool varies() const { return !rest_.empty(); }
  // The film's own σ and ψ where it does not vary.
  PointRoughness uniform() const { return uniform_; }

  // The faces' Rqs (rest, turn) at node n, between nodes a and b (their mean), and at
  // (s, t) of a cell with corners (i, j), (i+1, j), (i, j+1), (i+1, j+1) (bilinear).
  PointRoughness at_node(int n) const;
  PointRoughness between(int a, int b) const;
  PointRoughness in_cell(const std::array<int, 4>& corners, double s, double t) const;

  // row += c·(dRq/dd) of node n's face at rest (turning face) in its depth's column: c is
  // a kernel's slope in that face's Rq at the node.
  void add_rest(Assembler& a, Index row, double c, int n) const;
  void add_turn(Assembler& a, Index row, double c, int n) const;
  // The depth unknown node n's Rq of the face at rest (turning face) reads, and dRq/du there:
  // for slopes kept in the film's totals and added to rows later (DepthTerm).
  std::pair<Index, double> rest_column(int n) const;
  std::pair<Index, double> turn_column(int n) const;

 private:
  const Film* film_;
  PointRoughness uniform_;
  std::vector<ValueSlope> rest_, turn_;  // per node, per radial node (dRq/dd per scaled unknown)
  Index rest_offset_ = -1, turn_offset_ = -1;
};

}  // namespace twb
