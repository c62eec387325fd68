#include "physics/elastic_annulus.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>
#include <numbers>
#include <stdexcept>
#include <utility>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

namespace twb {

ElasticAnnulus::ElasticAnnulus(double inner_radius, double outer_radius, int radial_nodes, int circumferential_nodes,
                               double rigidity, double poisson)
    : inner_(inner_radius),
      outer_(outer_radius),
      dr_((outer_radius - inner_radius) / (radial_nodes - 1)),
      dtheta_(2.0 * std::numbers::pi / circumferential_nodes),
      rigidity_(rigidity),
      poisson_(poisson),
      nr_(radial_nodes),
      nt_(circumferential_nodes) {
  if (!(inner_radius > 0.0 && outer_radius > inner_radius) || radial_nodes < 3 || circumferential_nodes < 3)
    throw std::invalid_argument("ElasticAnnulus: an annulus 0 < r_i < r_o on at least 3 x 3 nodes");
  if (!(rigidity > 0.0) || !(poisson > -1.0 && poisson < 0.5))
    throw std::invalid_argument("ElasticAnnulus: a positive rigidity and a Poisson's ratio in (-1, 0.5)");
  for (int i = 0; i < nr_; ++i) {
    const double lo = std::max(inner_, radius(i) - 0.5 * dr_), hi = std::min(outer_, radius(i) + 0.5 * dr_);
    area_.push_back(0.5 * (hi * hi - lo * lo) * dtheta_);
  }
  add_w_rows();
  add_m_rows();
  add_rigid_conditions();
}

std::array<std::pair<int, double>, 3> ElasticAnnulus::edge_slope(int edge) const {
  const double h = 2.0 * dr_;
  if (edge == 0) return {{{0, -3.0 / h}, {1, 4.0 / h}, {2, -1.0 / h}}};
  return {{{nr_ - 1, 3.0 / h}, {nr_ - 2, -4.0 / h}, {nr_ - 3, 1.0 / h}}};
}

// ∮∂u/∂n ds of a node's control volume into `row_of(node)`'s row, u's column `column_of`,
// scaled by c: the radial faces' fluxes r·dθ·Δu/dr, the circumferential faces' ln(hi/lo)·Δu/dθ.
namespace {
template <class Add>
void add_laplacian(int nr, int nt, double inner, double outer, double dr, double dtheta, double c, int row_base,
                   int column_base, const Add& add) {
  auto node = [&](int i, int j) { return i * nt + ((j % nt) + nt) % nt; };
  for (int i = 0; i < nr; ++i) {
    const double r = inner + i * dr;
    const double lo = std::max(inner, r - 0.5 * dr), hi = std::min(outer, r + 0.5 * dr);
    const double around = c * std::log(hi / lo) / dtheta, across = c * (r + 0.5 * dr) * dtheta / dr;
    for (int j = 0; j < nt; ++j) {
      const int a = node(i, j), b = node(i, j + 1);
      add(row_base + a, column_base + b, around);
      add(row_base + a, column_base + a, -around);
      add(row_base + b, column_base + a, around);
      add(row_base + b, column_base + b, -around);
      if (i + 1 == nr) continue;
      const int o = node(i + 1, j);
      add(row_base + a, column_base + o, across);
      add(row_base + a, column_base + a, -across);
      add(row_base + o, column_base + a, across);
      add(row_base + o, column_base + o, -across);
    }
  }
}
}  // namespace

void ElasticAnnulus::add_w_rows() {
  const int n = nodes();
  add_laplacian(nr_, nt_, inner_, outer_, dr_, dtheta_, 1.0, 0, 0,
                [this](int r, int c, double v) { add(r, c, v); });
  for (int i = 0; i < nr_; ++i)
    for (int j = 0; j < nt_; ++j) add(node(i, j), n + node(i, j), -area(i));
  // The edges' outward flux w_r·r·dθ, w_r = r·m/(1 − ν) − w_θθ/r from M_r = 0 [E2].
  for (const int edge : {0, 1}) {
    const int i = edge == 0 ? 0 : nr_ - 1;
    const double r = radius(i), outward = edge == 0 ? -1.0 : 1.0;
    for (int j = 0; j < nt_; ++j) {
      const int a = node(i, j);
      add(a, n + a, outward * r * r * dtheta_ / (1.0 - poisson_));
      add(a, node(i, j + 1), -outward / dtheta_);
      add(a, node(i, j - 1), -outward / dtheta_);
      add(a, a, 2.0 * outward / dtheta_);
    }
  }
}

void ElasticAnnulus::add_m_rows() {
  const int n = nodes();
  add_laplacian(nr_, nt_, inner_, outer_, dr_, dtheta_, rigidity_, n, n,
                [this](int r, int c, double v) { add(r, c, v); });
  // The edges' outward flux D·m_r·r·dθ from V_r = 0 [E3] (edge_twisting).
  for (const EdgeTwist& t : edge_twisting()) {
    add(t.row, node(t.radial_node, t.angle + 1), t.coefficient);
    add(t.row, node(t.radial_node, t.angle), -2.0 * t.coefficient);
    add(t.row, node(t.radial_node, t.angle - 1), t.coefficient);
  }
  for (int i = 0; i < nr_; ++i)
    for (int j = 0; j < nt_; ++j) {
      const double x = radius(i) * std::cos(angle(j)), y = radius(i) * std::sin(angle(j));
      add(n + node(i, j), 2 * n + 0, -area(i));
      add(n + node(i, j), 2 * n + 1, -area(i) * x);
      add(n + node(i, j), 2 * n + 2, -area(i) * y);
    }
}

void ElasticAnnulus::add_rigid_conditions() {
  const int n = nodes();
  for (int i = 0; i < nr_; ++i)
    for (int j = 0; j < nt_; ++j) {
      const double x = radius(i) * std::cos(angle(j)), y = radius(i) * std::sin(angle(j));
      add(2 * n + 0, node(i, j), area(i));
      add(2 * n + 1, node(i, j), area(i) * x);
      add(2 * n + 2, node(i, j), area(i) * y);
    }
}

std::vector<double> ElasticAnnulus::right_side(std::span<const double> load,
                                               std::span<const double> thermal_curvature) const {
  const int n = nodes();
  if (load.size() != std::size_t(n) || thermal_curvature.size() != std::size_t(n))
    throw std::invalid_argument("ElasticAnnulus: a load and a thermal curvature per node");
  std::vector<double> b(std::size_t(size()), 0.0);
  for (int i = 0; i < nr_; ++i)
    for (int j = 0; j < nt_; ++j) {
      const int a = node(i, j);
      b[std::size_t(a)] = area(i) * (1.0 + poisson_) * thermal_curvature[std::size_t(a)];
      b[std::size_t(n + a)] = load[std::size_t(a)];
    }
  return b;
}

int ElasticAnnulus::rigidity_node(const Entry& e) const {
  const int n = nodes();
  if (e.row < n || e.row >= 2 * n || e.column >= 2 * n) return -1;
  return e.column < n ? kReplacedByTwisting : e.column - n;
}

namespace {
// A nodal field's combination at a place: (node, weight) pairs.
using Stencil = std::vector<std::pair<int, double>>;
Stencil combined(const Stencil& a, double ca, const Stencil& b, double cb) {
  Stencil out;
  for (const auto& [k, v] : a) out.emplace_back(k, ca * v);
  for (const auto& [k, v] : b) out.emplace_back(k, cb * v);
  return out;
}
}  // namespace

// [M2]: the m rows less (1 − ν)·∮ cof(∇∇w)·∇D · n ds, whose flux through a face of normal n
// and tangent t is H_tt·∂D/∂n − H_nt·∂D/∂t (H = ∇∇w in the face's frame; the twisting
// term's divergence form, ◊⁴(D, w) = ∇·(cof(H)·∇D)). Each face's flux leaves one control
// volume and enters the next, so the terms telescope as the Laplacian's do. On a radial
// face (i+½, j): H_tt = w_r/r + w_θθ/r², H_nt = w_rθ/r − w_θ/r², ∂D/∂t = D_θ/r; on a
// circumferential face (i, j+½): H_tt = w_rr, H_nt the same, ∂D/∂n = D_θ/r, ∂D/∂t = D_r;
// central differences between the face's nodes, one-sided in r at the edges, the
// circumferential face taken at the node's radius over the control volume's extent.
void ElasticAnnulus::add_twisting_terms(std::vector<TwistingTerm>& out) const {
  const int n = nodes();
  const double twist = (1.0 - poisson_) * rigidity_;
  // Face flux Φ = length·(a·b) between control volumes `from` (outward) and `to`.
  const auto add_flux = [&](int from, int to, double length, const Stencil& w, const Stencil& f) {
    for (const auto& [wk, wv] : w)
      for (const auto& [fk, fv] : f) {
        out.push_back({n + from, wk, fk, -twist * length * wv * fv});
        out.push_back({n + to, wk, fk, twist * length * wv * fv});
      }
  };
  const auto d_r = [&](int i, int j) -> Stencil {
    if (i == 0 || i == nr_ - 1) {
      Stencil slope;
      for (const auto& [ik, v] : edge_slope(i == 0 ? 0 : 1)) slope.emplace_back(node(ik, j), v);
      return slope;
    }
    return {{node(i + 1, j), 0.5 / dr_}, {node(i - 1, j), -0.5 / dr_}};
  };
  const auto d_rr = [&](int i, int j) -> Stencil {
    const double h2 = dr_ * dr_;
    const int step = i == nr_ - 1 ? -1 : 1;
    if (i > 0 && i < nr_ - 1) return {{node(i - 1, j), 1.0 / h2}, {node(i, j), -2.0 / h2}, {node(i + 1, j), 1.0 / h2}};
    if (nr_ < 4) return {{node(i, j), 1.0 / h2}, {node(i + step, j), -2.0 / h2}, {node(i + 2 * step, j), 1.0 / h2}};
    return {{node(i, j), 2.0 / h2}, {node(i + step, j), -5.0 / h2}, {node(i + 2 * step, j), 4.0 / h2},
            {node(i + 3 * step, j), -1.0 / h2}};
  };
  const double dt = dtheta_;
  for (int i = 0; i < nr_; ++i)
    for (int j = 0; j < nt_; ++j) {
      if (i + 1 < nr_) {
        const double r = radius(i) + 0.5 * dr_;
        Stencil h_tt{{node(i + 1, j), 1.0 / (dr_ * r)}, {node(i, j), -1.0 / (dr_ * r)}};
        Stencil h_nt, d_t;
        const double c2 = 0.5 / (dt * dt * r * r), c1 = 0.5 / (2.0 * dt);
        for (const int ii : {i, i + 1}) {
          h_tt.insert(h_tt.end(), {{node(ii, j + 1), c2}, {node(ii, j), -2.0 * c2}, {node(ii, j - 1), c2}});
          const double rate = ii == i ? -1.0 : 1.0;  // w_rθ: the outer pair less the inner
          h_nt.insert(h_nt.end(), {{node(ii, j + 1), rate / (2.0 * dt * dr_ * r) - c1 / (r * r)},
                                   {node(ii, j - 1), -rate / (2.0 * dt * dr_ * r) + c1 / (r * r)}});
          d_t.insert(d_t.end(), {{node(ii, j + 1), c1 / r}, {node(ii, j - 1), -c1 / r}});
        }
        const Stencil d_n{{node(i + 1, j), 1.0 / dr_}, {node(i, j), -1.0 / dr_}};
        add_flux(node(i, j), node(i + 1, j), r * dt, h_tt, d_n);
        add_flux(node(i, j), node(i + 1, j), -r * dt, h_nt, d_t);
      }
      const double r = radius(i);
      const double length = std::min(outer_, r + 0.5 * dr_) - std::max(inner_, r - 0.5 * dr_);
      const Stencil h_tt = combined(d_rr(i, j), 0.5, d_rr(i, j + 1), 0.5);
      const Stencil d_n{{node(i, j + 1), 1.0 / (r * dt)}, {node(i, j), -1.0 / (r * dt)}};
      const Stencil h_nt = combined(combined(d_r(i, j + 1), 1.0 / (dt * r), d_r(i, j), -1.0 / (dt * r)), 1.0,
                                    Stencil{{node(i, j + 1), 1.0 / (dt * r * r)}, {node(i, j), -1.0 / (dt * r * r)}},
                                    -1.0);
      const Stencil d_t = combined(d_r(i, j), 0.5, d_r(i, j + 1), 0.5);
      add_flux(node(i, j), node(i, j + 1), length, h_tt, d_n);
      add_flux(node(i, j), node(i, j + 1), -length, h_nt, d_t);
    }
}

// m_r = −(1 − ν)/r·∂θ g, g = w_rθ/r − w_θ/r²: the edge's outward flux D·m_r·r·dθ is
// −D(1 − ν)·(g_{j+½} − g_{j−½}), g at half angles from the one-sided radial slope of w_θ;
// each radial weight of the slope gives c·(w_{j+1} − 2w_j + w_{j−1}) on its ring.
std::vector<ElasticAnnulus::EdgeTwist> ElasticAnnulus::edge_twisting() const {
  std::vector<EdgeTwist> out;
  for (const int edge : {0, 1}) {
    const int ie = edge == 0 ? 0 : nr_ - 1;
    const double r = radius(ie), sign = (edge == 0 ? 1.0 : -1.0) * rigidity_ * (1.0 - poisson_);
    for (int j = 0; j < nt_; ++j)
      for (const auto& [ik, slope] : edge_slope(edge))
        out.push_back({nodes() + node(ie, j), ie, ik, j, sign * (slope / r - (ik == ie ? 1.0 / (r * r) : 0.0)) / dtheta_});
  }
  return out;
}

// [M3]: the edge's flux with D at each half angle the mean of its two nodes'.
void ElasticAnnulus::add_edge_twisting_moment(std::vector<TwistingTerm>& out) const {
  for (const EdgeTwist& t : edge_twisting())
    for (const int half : {1, -1}) {  // the flux's part c·(w_{j±1} − w_j) at j ± ½
      const double g = 0.5 * t.coefficient;
      for (const int f : {node(t.edge_node, t.angle), node(t.edge_node, t.angle + half)}) {
        out.push_back({t.row, node(t.radial_node, t.angle + half), f, g});
        out.push_back({t.row, node(t.radial_node, t.angle), f, -g});
      }
    }
}

std::vector<ElasticAnnulus::TwistingTerm> ElasticAnnulus::twisting_terms() const {
  std::vector<TwistingTerm> terms;
  add_twisting_terms(terms);
  add_edge_twisting_moment(terms);
  // One term per (row, column, node): the stencils repeat nodes.
  std::sort(terms.begin(), terms.end(), [](const TwistingTerm& a, const TwistingTerm& b) {
    return std::tie(a.row, a.column, a.node) < std::tie(b.row, b.column, b.node);
  });
  std::vector<TwistingTerm> merged;
  for (const TwistingTerm& t : terms) {
    if (!merged.empty() && merged.back().row == t.row && merged.back().column == t.column && merged.back().node == t.node)
      merged.back().value += t.value;
    else
      merged.push_back(t);
  }
  return merged;
}

ElasticAnnulus::Deflection ElasticAnnulus::solve(std::span<const double> load, std::span<const double> thermal_curvature,
                                                 std::span<const double> rigidity_factor) const {
  if (!rigidity_factor.empty() && rigidity_factor.size() != std::size_t(nodes()))
    throw std::invalid_argument("ElasticAnnulus: a rigidity factor per node, or none");
  std::vector<Eigen::Triplet<double>> triplets;
  for (const Entry& e : entries_) {
    const int k = rigidity_node(e);
    if (rigidity_factor.empty() || k == -1)
      triplets.emplace_back(e.row, e.column, e.value);
    else if (k >= 0)
      triplets.emplace_back(e.row, e.column, e.value * rigidity_factor[std::size_t(k)]);
  }
  if (!rigidity_factor.empty())
    for (const TwistingTerm& t : twisting_terms())
      triplets.emplace_back(t.row, t.column, t.value * rigidity_factor[std::size_t(t.node)]);
  Eigen::SparseMatrix<double> k(size(), size());
  k.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(k);
  if (lu.info() != Eigen::Success) throw std::runtime_error("ElasticAnnulus: the plate's matrix is singular");
  const std::vector<double> b = right_side(load, thermal_curvature);
  const Eigen::VectorXd x = lu.solve(Eigen::Map<const Eigen::VectorXd>(b.data(), Eigen::Index(b.size())));
  Deflection d;
  const int n = nodes();
  d.w.assign(x.data(), x.data() + n);
  d.m.assign(x.data() + n, x.data() + 2 * n);
  for (int k3 = 0; k3 < 3; ++k3) d.multipliers[std::size_t(k3)] = x[2 * n + k3];
  return d;
}

}  // namespace twb
