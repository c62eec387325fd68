// One evaluation of the loads a film puts on its bodies (docs/physics.md sections 3, 4,
// 6): what every cell of the film shares (its gap plane, the rules' point tables, the
// node temperatures, its gap), and the per-cell kernels, each integrating one kind of
// load over a cell into the cell's sums:
//   contact_cell.cpp   asperity contact force, its moments and the friction power
//   fluid_cell.cpp     fluid pressure force and moments, viscous shear torque and heat
//   film_loads.cpp     the loop over cells, the scatter of a cell's sums into the rows,
//                      and the boundary friction once the film's contact force is known
#pragma once

#include <array>
#include <span>
#include <type_traits>
#include <vector>

#include "model/assembly_totals.h"
#include "model/film_gap.h"
#include "model/film_roughness.h"
#include "model/film_loads_effect.h"

namespace twb {

// A Gauss point of a cell: local coordinates (s, t) in [0, 1]², position in the load
// frame, and weight r dr dθ.
struct CellPoint { double s, t, r, x, y, w; };

// One rule's points on the cells of a film: every point's cos/sin follows from its
// cell's node angle by the addition theorem, without calling sincos per point.
class CellRule {
 public:
  CellRule(const GaussRule& rule, const FilmMesh& mesh, const std::vector<double>& cos_node,
           const std::vector<double>& sin_node);
  std::size_t size() const { return rule_.points.size(); }
  CellPoint point(int i, int j, std::size_t gs, std::size_t gt) const {
    const double s = rule_.points[gs], r = mesh_.radius(i) + s * mesh_.dr();
    return CellPoint{s, rule_.points[gt], r, r * (cos_node_[j] * cos_[gt] - sin_node_[j] * sin_[gt]),
                     r * (sin_node_[j] * cos_[gt] + cos_node_[j] * sin_[gt]),
                     rule_.weights[gs] * rule_.weights[gt] * r * mesh_.dr() * mesh_.dtheta()};
  }

 private:
  const GaussRule& rule_;
  const FilmMesh& mesh_;
  const std::vector<double>& cos_node_;
  const std::vector<double>& sin_node_;
  std::vector<double> cos_, sin_;
};

// The bilinear hats of a cell's corners at local (s, t).
inline std::array<double, 4> corner_hats(double s, double t) {
  return {(1 - s) * (1 - t), s * (1 - t), (1 - s) * t, s * t};
}

// Calls integrate(std::bool_constant<gradients>): one instantiation per case, so the
// residual-only sums carry no test for the gradients in their inner loops.
template <class Integrate>
void with_gradients(bool gradients, const Integrate& integrate) {
  if (gradients)
    integrate(std::true_type{});
  else
    integrate(std::false_type{});
}

// Cell (i, j) of a film at a state: its corners (i, j), (i+1, j), (i, j+1), (i+1, j+1),
// their pressure columns, and the corner values the kernels interpolate.
struct FilmCell {
  int i = 0, j = 0;
  std::array<int, 4> node{};
  std::array<Index, 4> p_col{-1, -1, -1, -1};
  std::array<double, 4> p_node{}, t_node{};
  CellGap gap;  // the gap beyond its plane, and its range over the cell (film_gap.h)
};

// A cell's integrals with their gradients. Rigid-body gradients are gathered against
// the moment arms a = (1, y, −x) of (F, Mx, My): the gap gradient is dh = g ⊙ a
// (Film::gap_gradient), so every integral of f·dh is g ⊙ (integral of f·a), and g is
// applied once per cell, in the scatter.
struct CellLoads {
  std::array<double, 3> load_val{};                   // F, Mx, My
  std::array<std::array<double, 3>, 3> load_rigid{};  // against the arms
  std::array<std::array<double, 4>, 3> load_p{};      // against the corner pressures
  std::array<double, 4> vheat{};                      // viscous heat per corner node
  std::array<std::array<double, 3>, 4> vheat_rigid{};
  std::array<std::array<double, 4>, 4> vheat_t{};
  // The same against the corner shapes δ_k (the parts of the gap, gap_contribution.h).
  std::array<std::array<double, 4>, 3> load_shape{};
  std::array<std::array<double, 4>, 4> vheat_shape{};
  // The same against each face's Rq at the corners, where the faces run in (film_roughness.h).
  std::array<std::array<double, 4>, 4> vheat_rest{}, vheat_turn{};
  std::array<std::array<double, 4>, 3> load_rest{}, load_turn{};
  std::array<std::array<double, 4>, 4> power_rest{}, power_turn{};  // friction power per corner
  std::array<std::array<double, 4>, 4> power_shape{};  // friction power per corner, against δ
  double contact_force = 0;                            // the cell's contact force
  std::array<double, 3> contact_rigid{};               // its gradient against the arms
  // With the elastic washer: the force on each corner's hat ∫ p·N_k dA, fluid and contact
  // (its load on the plate, docs/physics.md section 21), against the arms, the corner
  // pressures, the corner shapes and each face's Rq at the corners.
  std::array<double, 4> corner_force{};
  std::array<std::array<double, 3>, 4> corner_force_rigid{};
  std::array<std::array<double, 4>, 4> corner_force_p{}, corner_force_shape{};
  std::array<std::array<double, 4>, 4> corner_force_rest{}, corner_force_turn{};
};

struct FilmLoadPass {
  FilmLoadPass(const BearingModel& model, const FilmLoadRules& rules, std::span<const double> u, const Film& film,
               const Assembler& a);

  // The cell's corners and the gap's range over it.
  FilmCell cell(int i, int j) const;
  // Whether contact can exist on the cell: its least gap within the cutoff (beyond it
  // p_c < 1e-20 p(0), whose force is below 1e-12 of any load: skipping it is invisible
  // to Newton). Every cell in a structure pass.
  bool near_contact(const FilmCell& cell) const;
  void contact_on_cell(const FilmCell& cell, CellLoads& loads, FilmTotals& tot);  // contact_cell.cpp
  void fluid_on_cell(const FilmCell& cell, CellLoads& loads, FilmTotals& tot);    // fluid_cell.cpp
  void scatter(const FilmCell& cell, const CellLoads& loads, Assembler& a) const;
  // The corners' forces into the washer plate's rows (with the elastic washer).
  void load_plate(const FilmCell& cell, const CellLoads& loads, Assembler& a) const;
  // The cell's friction power's slopes in the corners' shapes and Rqs into the film's totals.
  void keep_power_slopes(const FilmCell& cell, const CellLoads& loads, FilmTotals& tot) const;
  // row += c·(slopes in the corners' Rqs), where the faces run in.
  void add_roughness_slopes(const FilmCell& cell, Index row, double c, const std::array<double, 4>& by_rest,
                            const std::array<double, 4>& by_turn, Assembler& a) const;
  // Boundary friction f·p_cont into the heat rows, once the film's totals are complete.
  void friction(FilmTotals& tot, Assembler& a) const;

  const BearingModel& model;
  std::span<const double> u;
  const Film& film;
  const FilmMesh& mesh;
  bool structural, jac, hydro, heat, contact;
  bool plate;  // the washer bends: the corners' forces are gathered for its rows
  double omega, cutoff;
  FilmGap gap;
  FilmRoughness roughness;
  bool shaped;  // the gap has a shape δ: its slopes in the corner shapes are gathered
  PlaneOverCells plane;
  std::array<Index, 3> rigid_cols;
  std::array<double, 3> g;  // film.gap_gradient = g ⊙ (1, y, −x): the slopes per unit moment arm
  std::vector<double> cos_node, sin_node;
  CellRule contact_rule, smooth_rule, flat_rule;
  bool flat_rule_is_cheaper;
  // Rows of the rigid-body balance this film loads (eqs [34]-[37]) with their scales.
  struct RowSign { Index row; double force, mx, my; };
  std::vector<RowSign> rows;
  std::vector<double> node_t;  // viscosity temperature per node
  Index force_row;             // the sliding film's contact-force row, or -1

  // Scratch of the kernels, kept between cells.
  std::vector<CellPoint> contact_points;
  std::vector<double> contact_h;
  std::vector<ValueSlope> contact_p;
  std::vector<std::array<double, 2>> contact_by_rq;  // ∂p/∂Rq of each face, where they run in
  std::vector<double> point_t, point_h;
  std::vector<ValueSlope> point_mu, point_gap;
  std::vector<PointRoughness> point_rough;  // where the faces run in
};

}  // namespace twb
