// The modified Reynolds equation [1] on the sliding film (MODEL.md section 3), finite
// volumes on the polar grid (second order), with the Reynolds cavitation condition as
// the complementarity p ≥ 0, w ≥ 0, p·w = 0 solved inside Newton through the
// Fischer–Burmeister function of the scaled pair (p̂, ŵ).
//
// w is the net volumetric outflow of a node's control volume: Couette outflow minus
// Poiseuille inflow. Where the film ruptures (p = 0, diverging gap) more oil leaves
// than enters, so w ≥ 0 there, and w = 0 wherever p > 0.
#include <array>
#include <cmath>

#include "twb/model/bearing_model.h"
#include "twb/physics/average_gap.h"
#include "twb/physics/flow_factors.h"

namespace twb {

namespace {

// Fischer–Burmeister φ(a, b) = a + b − √(a² + b²) and its partial derivatives; at the
// kink (0, 0) any element of the generalized Jacobian serves semismooth Newton.
struct FischerBurmeister {
  double value, da, db;
};
FischerBurmeister fischer_burmeister(double a, double b) {
  const double n = std::hypot(a, b);
  if (n == 0.0) return {0.0, 1.0 - std::sqrt(0.5), 1.0 - std::sqrt(0.5)};
  return {a + b - n, 1.0 - a / n, 1.0 - b / n};
}

}  // namespace

void BearingModel::assemble_reynolds(std::span<const double> u, const Film& film, Assembler& a) const {
  const bool jac = a.wants_jacobian();
  const FilmMesh& m = film.mesh;
  const int nr = m.radial_nodes(), nt = m.circumferential_nodes();
  const RigidPosition q = position(u);
  const double c = film.clearance_unknown == 0 ? q.c1 : q.c2;
  const double pa = -film.sign * q.gamma_y - film.imposed_tilt;
  const double pb = film.sign * q.gamma_x;
  const std::array<Index, 3> rigid_cols{rigid_offset_ + film.clearance_unknown, rigid_offset_ + 1,
                                        rigid_offset_ + 2};
  const double omega = scene_.operating.speed;
  const bool factors = scene_.effects.flow_factors;
  const double sigma = film.sigma;

  auto p_col = [&](int i, int j) -> Index {
    return (i > 0 && i < nr - 1) ? film.pressure_offset + Index(i - 1) * nt + m.wrap(j) : -1;
  };
  auto p_val = [&](int i, int j) { Index k = p_col(i, j); return k >= 0 ? p_ref_ * u[k] : 0.0; };

  std::vector<double> node_t(m.node_count());
  std::vector<LinearForm> node_t_form(m.node_count());
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nt; ++j)
      node_t[m.node(i, j)] = viscosity_temperature(u, film, i, j, jac ? &node_t_form[m.node(i, j)] : nullptr);

  // Poiseuille conductance φ·max(h, 0)³/(12 μ) at a face, and its slopes in h and T.
  struct Conductance { double g, dg_dh, dg_dt; };
  auto conductance = [&](double h, double t_face) {
    const double hp = std::max(h, 0.0);
    const ValueSlope mu = viscosity(t_face);
    ValueSlope phi{1.0, 0.0};
    if (factors) {
      const ValueSlope f = pressure_flow_factor(h / sigma);
      phi = {f.value, f.slope / sigma};
    }
    const double g = phi.value * hp * hp * hp / (12.0 * mu.value);
    const double dg_dh = (phi.slope * hp * hp * hp + phi.value * 3.0 * hp * hp) / (12.0 * mu.value);
    return Conductance{g, dg_dh, -g * mu.slope / mu.value};
  };

  // A face flux Q (m³/s) from node A to node B, and its gradient: rigid (via h at the
  // face), the two pressures, the two node temperatures.
  auto add_face = [&](int ia, int ja, int ib, int jb, double q_val, const std::array<double, 3>& dq_rigid,
                      double dq_dpa, double dq_dpb, double dq_dta, double dq_dtb) {
    const Index ra = p_col(ia, ja), rb = p_col(ib, jb);
    const Index na = m.node(ia, ja), nb = m.node(ib, jb);
    for (auto [row, sign] : {std::pair{ra, 1.0}, std::pair{rb, -1.0}}) {
      if (row < 0) continue;
      a.add_residual(row, sign * q_val);
      if (!jac) continue;
      for (int d = 0; d < 3; ++d) a.add_derivative(row, rigid_cols[d], sign * dq_rigid[d]);
      a.add_derivative(row, ra, sign * dq_dpa * p_ref_);
      a.add_derivative(row, rb, sign * dq_dpb * p_ref_);
      a.add_form(row, sign * dq_dta, node_t_form[na]);
      a.add_form(row, sign * dq_dtb, node_t_form[nb]);
    }
  };

  // Radial faces between (i, j) and (i+1, j), at r_{i+1/2}.
  for (int i = 0; i < nr - 1; ++i) {
    const double rf = m.radius(i) + 0.5 * m.dr();
    for (int j = 0; j < nt; ++j) {
      if (p_col(i, j) < 0 && p_col(i + 1, j) < 0) continue;
      const double th = m.angle(j), x = rf * std::cos(th), y = rf * std::sin(th);
      const double h = c + pa * x + pb * y;
      const std::array<double, 3> dh{sigma_ref_, film.sign * y * gamma_ref_, -film.sign * x * gamma_ref_};
      const double tf = 0.5 * (node_t[m.node(i, j)] + node_t[m.node(i + 1, j)]);
      const Conductance g = conductance(h, tf);
      const double geom = rf * m.dtheta() / m.dr();
      const double dp = p_val(i + 1, j) - p_val(i, j);
      const double qf = -g.g * geom * dp;
      std::array<double, 3> dq{};
      for (int d = 0; d < 3; ++d) dq[d] = -g.dg_dh * geom * dp * dh[d];
      const double dq_dt = -g.dg_dt * geom * dp * 0.5;
      add_face(i, j, i + 1, j, qf, dq, g.g * geom, -g.g * geom, dq_dt, dq_dt);
    }
  }

  // Circumferential faces between (i, j) and (i, j+1), at θ_{j+1/2}: Poiseuille plus
  // Couette (V/2)(h̄T + σ φs) with V = ω r (or h without flow factors).
  for (int i = 1; i < nr - 1; ++i) {
    const double r = m.radius(i);
    for (int j = 0; j < nt; ++j) {
      const double th = m.angle(j) + 0.5 * m.dtheta(), x = r * std::cos(th), y = r * std::sin(th);
      const double h = c + pa * x + pb * y;
      const std::array<double, 3> dh{sigma_ref_, film.sign * y * gamma_ref_, -film.sign * x * gamma_ref_};
      const double tf = 0.5 * (node_t[m.node(i, j)] + node_t[m.node(i, j + 1)]);
      const Conductance g = conductance(h, tf);
      const double geom = m.dr() / (r * m.dtheta());
      const double dp = p_val(i, j + 1) - p_val(i, j);
      ValueSlope carried{h, 1.0};
      if (factors) {
        const ValueSlope gap = average_gap(h, sigma);
        const ValueSlope phis = shear_flow_factor_Phi_s(h / sigma);
        carried = {gap.value + sigma * film.shear_weight * phis.value, gap.slope + film.shear_weight * phis.slope};
      }
      const double couette = 0.5 * omega * r * m.dr();
      const double qf = -g.g * geom * dp + couette * carried.value;
      std::array<double, 3> dq{};
      for (int d = 0; d < 3; ++d) dq[d] = (-g.dg_dh * geom * dp + couette * carried.slope) * dh[d];
      const double dq_dt = -g.dg_dt * geom * dp * 0.5;
      add_face(i, j, i, j + 1, qf, dq, g.g * geom, -g.g * geom, dq_dt, dq_dt);
    }
  }

  // Wrap each node's flow balance in the complementarity function.
  if (a.mode() != Assembler::Mode::values) return;
  for (int i = 1; i < nr - 1; ++i) {
    for (int j = 0; j < nt; ++j) {
      const Index row = p_col(i, j);
      const double scale = flow_scale_[row - film.pressure_offset];
      const double w_hat = a.residual_value(row) / scale;
      const FischerBurmeister fb = fischer_burmeister(u[row], w_hat);
      a.set_residual(row, fb.value);
      if (!jac) continue;
      a.scale_row(row, fb.db / scale);
      a.add_derivative(row, row, fb.da);
    }
  }
}

}  // namespace twb
