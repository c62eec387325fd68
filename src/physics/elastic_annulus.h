// The washer as a Kirchhoff plate (docs/physics.md section 21): an annulus with free
// edges on a polar grid of nodes, in the mixed form [E1]-[E3], its rigid modes fixed by
// ∫w dA = ∫w·x dA = ∫w·y dA = 0 with three multipliers. Unknowns: w at every node (m),
// then m = ∇²w − (1 + ν)·κ_T at every node (1/m), then λ0, λ1, λ2 (Pa, Pa/m, Pa/m).
//
// Every row is a control volume's balance (the nodes' cells, half cells at the edges):
//   w rows:  ∮∂w/∂n ds − A·m = A·(1 + ν)·κ_T, the edge's flux from M_r = 0 [E2]
//   m rows:  D·∮∂m/∂n ds − A·(λ0 + λ1·x + λ2·y) = F, the edge's flux from V_r = 0 [E3]
// F the node's share of the load (N). The edge fluxes of [E3] telescope round each edge,
// so that the loads' sum is what the m rows' fluxes balance: λ0 is zero wherever the load
// is in equilibrium.
#pragma once

#include <array>
#include <span>
#include <vector>

namespace twb {

class ElasticAnnulus {
 public:
  // radial_nodes ≥ 3 (the edges' one-sided differences), circumferential_nodes ≥ 3;
  // rigidity D = E·t³/(12(1 − ν²)) (N·m), poisson ν in (−1, 0.5).
  ElasticAnnulus(double inner_radius, double outer_radius, int radial_nodes, int circumferential_nodes,
                 double rigidity, double poisson);

  int nodes() const { return nr_ * nt_; }
  int size() const { return 2 * nodes() + 3; }
  int node(int i, int j) const { return i * nt_ + ((j % nt_) + nt_) % nt_; }
  double radius(int i) const { return inner_ + i * dr_; }
  double angle(int j) const { return j * dtheta_; }
  // The control volume of radial node i (every angle's): its area (m²).
  double area(int i) const { return area_[std::size_t(i)]; }

  // The operator's entries (row, column, value): constant, the loads and κ_T on the right.
  struct Entry {
    int row, column;
    double value;
  };
  const std::vector<Entry>& entries() const { return entries_; }
  // Where the rigidity varies over the plate, D_k = D·f_k at node k (docs/physics.md
  // section 23, [M2]-[M3]), the operator is entries() with an m row's flux of node k's m
  // scaled by f_k, the edges' [E3] w entries replaced, and the twisting terms added: the
  // plate's (1 − ν)·◊⁴(D, w) as the fluxes of cof(∇∇w)·∇D through the control volumes'
  // faces, and the edges' twisting moment with D at the half angles. Each term is
  // value·w_column·f_node (N/m·… as the entry it adds to).
  static constexpr int kReplacedByTwisting = -2;
  // The node whose f scales an entry; −1: none (the w rows, the rigid modes);
  // kReplacedByTwisting: the edges' [E3] w entries, which twisting_terms() carry instead.
  int rigidity_node(const Entry& e) const;
  struct TwistingTerm {
    int row, column, node;
    double value;
  };
  // Built on each call (one term per (row, column, node)): only a plate whose rigidity
  // varies needs them, so a constant plate's construction does not pay for them.
  std::vector<TwistingTerm> twisting_terms() const;
  // The right side: each node's load F (N) and free thermal curvature κ_T (1/m).
  std::vector<double> right_side(std::span<const double> load, std::span<const double> thermal_curvature) const;

  // The deflection under those (Eigen's sparse LU: for checks; the bearing's Newton
  // solves the same rows within its system), with each node's rigidity D·factor where
  // `rigidity_factor` has one per node (empty: D everywhere).
  struct Deflection {
    std::vector<double> w, m;
    std::array<double, 3> multipliers{};
  };
  Deflection solve(std::span<const double> load, std::span<const double> thermal_curvature,
                   std::span<const double> rigidity_factor = {}) const;

 private:
  void add(int row, int column, double value) { entries_.push_back({row, column, value}); }
  void add_w_rows();
  void add_m_rows();
  void add_rigid_conditions();
  void add_twisting_terms(std::vector<TwistingTerm>& out) const;
  void add_edge_twisting_moment(std::vector<TwistingTerm>& out) const;
  // The edges' [E3] flux: row `row` (edge node (edge_node, angle)) takes
  // coefficient·(w_{j+1} − 2w_j + w_{j−1}) on ring radial_node.
  struct EdgeTwist {
    int row, edge_node, radial_node, angle;
    double coefficient;
  };
  std::vector<EdgeTwist> edge_twisting() const;
  // d/dr at an edge node's radius by the one-sided second-order difference, as weights on
  // radial nodes (i0, i0 ± 1, i0 ± 2): `edge` 0 inner, 1 outer.
  std::array<std::pair<int, double>, 3> edge_slope(int edge) const;

  double inner_, outer_, dr_, dtheta_, rigidity_, poisson_;
  int nr_, nt_;
  std::vector<double> area_;
  std::vector<Entry> entries_;
};

}  // namespace twb
