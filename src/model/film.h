// A film between two bodies (docs/physics.md section 1): its grid, its gap in the
// rigid-body unknowns, and where its nodes' unknowns lie. Every effect that reads a
// film's gap, the gap's slopes or a node's column reads them here, so that a new face
// feature or a new field of the film changes this one place.
#pragma once

#include <array>
#include <cmath>
#include <optional>

#include "model/face_relief.h"
#include "twb/model/bearing_state.h"
#include "twb/model/film_mesh.h"
#include "system/sparse_pattern.h"

namespace twb {

enum class ComponentId { carrier = 0, washer = 1, gear = 2 };

// The gap plane h = c + a·x + b·y (m) of a film at a rigid-body position, x and y in the
// load frame. Linear along every ray, so over a disc of radius r about the axis it is
// least along −(a, b), on the rim.
struct GapPlane {
  double c = 0, a = 0, b = 0;
  double at(double x, double y) const { return c + a * x + b * y; }
  double least_within(double r) const { return c - std::hypot(a, b) * r; }
};

// The gap is a plane in the unknowns (docs/physics.md section 1):
//   h = c + s·(γx·y − γy·x) − tilt·x
// film 1 (carrier–washer): c = c1 = z_w,              s = +1, tilt = 0
// film 2 (washer–gear):    c = c2 = z_g − z_w − t_w,  s = −1, tilt = γ_tilt
// plus the node shapes δ of the parts the effects register (gap_contribution.h: thermal
// deformation's, film_shape.cpp), plus the face's relief g (grooves, shaped lands:
// face_relief.h), which is constant in the unknowns; film_gap.h composes them.
struct Film {
  int number = 1;
  FilmMesh mesh;
  ComponentId lower, upper;
  int clearance_unknown = 0;  // 0 for c1, 3 for c2 within the rigid block
  double sign = 1.0;
  double imposed_tilt = 0.0;
  bool sliding = false;
  FaceRelief relief{};            // flat unless the washer's face on this film is grooved
  // The pressure (Pa, gauge) its inner edge holds: the oil supply's where the film is fed
  // from the bore (docs/physics.md section 14), else ambient; the outer edge is ambient.
  double inner_edge_pressure = 0.0;
  // With oil supplied into the grooves: the pressure every node on a groove holds
  // (fed_node); none without.
  std::optional<double> groove_pressure{};
  double sigma = 0.0;             // combined RMS roughness
  double shear_weight = 0.0;      // [(σ_moving/σ)² − (σ_fixed/σ)²], eq [3]
  Index pressure_offset = -1;     // interior nodes (radial 1..Nr-2), -1 without hydrodynamics
  Index content_offset = -1;      // film content θ at the same nodes, cavitation: jfo only (docs/physics.md 12)
  Index temperature_offset = -1;  // film-node temperatures, -1 without thermal
  // The rigid body's unknowns (z_w, γx, γy, z_g) and their scales: physical = scale · unknown.
  Index rigid_offset = 0;
  double clearance_scale = 0.0, tilt_scale = 0.0;

  double clearance(const RigidPosition& q) const { return clearance_unknown == 0 ? q.c1 : q.c2; }
  GapPlane plane(const RigidPosition& q) const {
    return {clearance(q), -sign * q.gamma_y - imposed_tilt, sign * q.gamma_x};
  }
  // The plane at a film node, summed in the order of the physics' form above: the heat
  // paths, the least gap and the reported fields were computed so before the plane had
  // one object, and their results (W_d among them) stay bit-identical. The same plane
  // as GapPlane::at up to the last digit; the relief is added by the caller.
  double node_gap(const RigidPosition& q, double x, double y) const {
    return clearance(q) + sign * (q.gamma_x * y - q.gamma_y * x) - imposed_tilt * x;
  }
  double node_gap_polar(const RigidPosition& q, double r, double theta) const {
    return node_gap(q, r * std::cos(theta), r * std::sin(theta));
  }
  // ∂h/∂(ĉ, γ̂x, γ̂y) at (x, y), in the scaled unknowns of rigid_columns().
  std::array<double, 3> gap_gradient(double x, double y) const {
    return {clearance_scale, sign * y * tilt_scale, -sign * x * tilt_scale};
  }
  std::array<Index, 3> rigid_columns() const {
    return {rigid_offset + clearance_unknown, rigid_offset + 1, rigid_offset + 2};
  }

  // The column of a field at grid node (i, j), −1 where the field has none there (the
  // pressure and the content live on the interior nodes: FilmMesh::interior_node).
  Index pressure_column(int i, int j) const { return column_of(pressure_offset, mesh.interior_node(i, j)); }
  Index content_column(int i, int j) const { return column_of(content_offset, mesh.interior_node(i, j)); }
  Index temperature_row(int node) const { return temperature_offset + node; }
  // The pressure an edge node (no unknown there) holds.
  double edge_pressure(int i) const { return i == 0 ? inner_edge_pressure : 0.0; }
  // An interior node on a fed groove: its pressure unknown holds the supply's (and its
  // content is full), a boundary of the lands' Reynolds equation like the edges.
  bool fed_node(int i, int j) const {
    return groove_pressure && i > 0 && i < mesh.radial_nodes() - 1 && relief.on_groove(i, j);
  }

 private:
  static Index column_of(Index offset, Index interior) { return offset >= 0 && interior >= 0 ? offset + interior : -1; }
};

}  // namespace twb
