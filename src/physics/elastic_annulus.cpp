#include "physics/elastic_annulus.h"

#include <cmath>
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
  // The edges' outward flux D·m_r·r·dθ, m_r = −(1 − ν)/r·∂θ g, g = w_rθ/r − w_θ/r², from
  // V_r = 0 [E3]: −D(1 − ν)·(g_{j+½} − g_{j−½}) outward, g at half angles from the
  // one-sided radial slope of w_θ.
  for (const int edge : {0, 1}) {
    const int ie = edge == 0 ? 0 : nr_ - 1;
    const double r = radius(ie), sign = (edge == 0 ? 1.0 : -1.0) * rigidity_ * (1.0 - poisson_);
    for (int j = 0; j < nt_; ++j) {
      const int row = n + node(ie, j);
      for (const auto& [ik, slope] : edge_slope(edge)) {
        const double c = (slope / r - (ik == ie ? 1.0 / (r * r) : 0.0)) / dtheta_;
        add(row, node(ik, j + 1), sign * c);
        add(row, node(ik, j), -2.0 * sign * c);
        add(row, node(ik, j - 1), sign * c);
      }
    }
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

ElasticAnnulus::Deflection ElasticAnnulus::solve(std::span<const double> load,
                                                 std::span<const double> thermal_curvature) const {
  std::vector<Eigen::Triplet<double>> triplets;
  for (const Entry& e : entries_) triplets.emplace_back(e.row, e.column, e.value);
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
