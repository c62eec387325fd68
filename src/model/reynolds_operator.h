// The finite-volume flow balance of one film on its polar grid (docs/physics.md section 3):
// the discretization of the Reynolds equation, and nothing else.
//
// Every interior node (i, j), 1 ≤ i ≤ Nr−2, owns the control volume
// [r_i − Δr/2, r_i + Δr/2] × [θ_j − Δθ/2, θ_j + Δθ/2]; its four faces are shared with its
// neighbours, so the balance is conservative. The flux through a face, from node A to
// node B, is second order: the exact flux
//   q = −g ∇p + (ω r / 2) h̄ e_θ,   g = φ h³ / (12 μ)   (docs/physics.md section 3, in flux form)
// integrated over the face by the midpoint rule, with ∇p by the central difference of
// the two nodal pressures:
//   Q = −g · geometry · (p_B − p_A) + (ω r / 2) · carried · couette_width
// where g and carried (the gap the moving surface drags: h̄T + σ φs, or h) are taken at
// the face midpoint. The net outflow w of a control volume is the sum of its faces'
// outward fluxes; the Reynolds equation is w = 0 where the film is full.
//
// Face quantities (g, carried) are the caller's: the bearing model evaluates them with
// their slopes in the unknowns, tests from a manufactured film. Pressures are 0 at both
// radial edges (ambient) and periodic in θ.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "twb/model/film_mesh.h"

namespace twb {

// One face between neighbouring nodes A and B, B one step outward in r (radial face) or
// forward in θ (circumferential face). A positive flux flows from A to B.
struct ReynoldsFace {
  enum class Kind { radial, circumferential };
  Kind kind;
  int index;           // 0 … face_count()−1: position in face-data arrays and in the visiting order
  int ia, ja, ib, jb;  // mesh nodes A and B (j already wrapped)
  int a, b;            // interior ordinals of A and B, −1 on a film edge (p = 0 there)
  double r, theta;     // face midpoint: where g and carried are evaluated
  double geometry;     // face length / node distance: r_{i+½}Δθ/Δr (radial), Δr/(r_iΔθ) (circumferential)
  double couette_width;  // face length crossed by the Couette flow: Δr (circumferential), 0 (radial)

  // The two control volumes the flux enters, with the sign that makes it their outflow.
  struct End { int node; double sign; };
  std::array<End, 2> ends() const { return {{{a, 1.0}, {b, -1.0}}}; }
};

// A face flux and its partial derivatives in the face quantities and the two pressures.
struct ReynoldsFaceFlux {
  double q;            // m³/s from A to B
  double dq_dg, dq_dcarried, dq_dpa, dq_dpb;
};

class ReynoldsOperator {
 public:
  // The mesh must outlive the operator.
  explicit ReynoldsOperator(const FilmMesh& mesh) : mesh_(mesh) {}

  const FilmMesh& mesh() const { return mesh_; }

  // Interior nodes carry the pressure unknowns, ordinal (i − 1)·Nθ + j; −1 on the edges.
  int interior_count() const;
  int interior_index(int i, int j) const;

  // The control volume of an interior node, over which w is the net outflow.
  struct ControlVolume { double r_lo, r_hi, theta_lo, theta_hi; };
  ControlVolume control_volume(int i, int j) const;

  // Face geometry factors (face length / node distance), see ReynoldsFace::geometry.
  double radial_geometry(int i) const;           // face between rows i and i+1
  double circumferential_geometry(int i) const;  // faces on row i

  // Faces touching at least one interior node: radial faces first (row by row), then
  // circumferential faces of the interior rows. Indices are dense in this order.
  int face_count() const;
  ReynoldsFace radial_face(int i, int j) const;           // between (i, j) and (i+1, j)
  ReynoldsFace circumferential_face(int i, int j) const;  // between (i, j) and (i, j+1)
  template <class Visit>
  void for_each_face(Visit&& visit) const;
  // The circumferential face of an edge row's half volume [r_i, r_i + Δr/2] (or its mirror
  // at the outer edge), between (i, j) and (i, j+1): the Couette flow alone crosses it (the
  // edge's pressure is uniform). No balance of the Reynolds equation has it; the oil's heat
  // does (convection, docs/physics.md section 15). a = b = −1, index −1.
  ReynoldsFace edge_face(int i, int j) const;

  // Mass-conserving cavitation (docs/physics.md section 12): the node whose film content θ the
  // Couette flow carries through a face, the one the sliding comes from (first-order
  // upwind: a full film, θ = 1, is discretized as above); −1 for a radial face, which
  // the Couette flow does not cross. The flux is then flux(…, θ_upwind · carried, …).
  static int upwind_node(const ReynoldsFace& face, double omega) {
    if (face.kind == ReynoldsFace::Kind::radial) return -1;
    return omega >= 0 ? face.a : face.b;
  }

  // The discrete face flux (formula above) with its partial derivatives.
  static ReynoldsFaceFlux flux(const ReynoldsFace& face, double omega, double g, double carried, double pa,
                               double pb);

  // Net outflow w (m³/s) of every interior control volume. conductance and carried are
  // indexed by ReynoldsFace::index (carried is not read on radial faces); pressure by
  // interior ordinal, in Pa.
  std::vector<double> net_outflow(double omega, std::span<const double> conductance,
                                  std::span<const double> carried, std::span<const double> pressure) const;

  // For fixed face quantities w is affine in the pressures: w(p) = M p + w(0). The
  // entries of M, ∂w_row/∂p_col by interior ordinal (duplicates to be summed), for
  // solving the film alone.
  struct Coefficient { int row, col; double value; };
  std::vector<Coefficient> pressure_coefficients(std::span<const double> conductance) const;

 private:
  int radial_face_count() const;
  const FilmMesh& mesh_;
};

template <class Visit>
void ReynoldsOperator::for_each_face(Visit&& visit) const {
  const int nr = mesh_.radial_nodes(), nt = mesh_.circumferential_nodes();
  if (nr < 3) return;  // no interior node, no balance
  for (int i = 0; i < nr - 1; ++i)
    for (int j = 0; j < nt; ++j) visit(radial_face(i, j));
  for (int i = 1; i < nr - 1; ++i)
    for (int j = 0; j < nt; ++j) visit(circumferential_face(i, j));
}

}  // namespace twb
