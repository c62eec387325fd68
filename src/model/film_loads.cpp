// Loads a film puts on its bounding bodies, integrated over each cell of its polar
// grid: fluid and contact force with their moments (eqs [31]-[33]), friction and
// viscous torque (eq [39]), and the heat generated (eqs [19], [20]) spread onto the
// film nodes with the bilinear hats (docs/physics.md sections 3, 4, 6).
//
// Contact, friction and shear vary steeply near the tight rim, within a fraction of a
// cell, so cells near contact use a high-order Gauss rule on the exact plane h(x, y)
// rather than nodal values times node areas.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "assembly_totals.h"
#include "physics/average_gap.h"
#include "physics/friction_law.h"

namespace twb {

namespace {

// Least and greatest value of the plane h = c + a·x + b·y over the polar cell
// [r0, r1] × [t0, t1]: linear along rays, so each is at a corner or on an arc where the
// direction (cos θ, sin θ) is opposite to (a, b) (least) or along it (greatest). Those
// two directions are the plane's, the same for every cell: their angles are found once.
struct GapRange { double least, greatest; };
class PlaneOverCells {
 public:
  PlaneOverCells(double c, double a, double b)
      : c_(c), a_(a), b_(b), tilted_(a != 0.0 || b != 0.0), down_(std::atan2(-b, -a)), up_(std::atan2(b, a)) {}

  GapRange range(double r0, double r1, double t0, double t1, double c0, double s0, double c1, double s1) const {
    const double e0 = a_ * c0 + b_ * s0, e1 = a_ * c1 + b_ * s1;
    const std::array<double, 4> corners{c_ + r0 * e0, c_ + r0 * e1, c_ + r1 * e0, c_ + r1 * e1};
    GapRange range{*std::min_element(corners.begin(), corners.end()),
                   *std::max_element(corners.begin(), corners.end())};
    if (!tilted_) return range;
    // Along the plane's steepest descent (ascent) the gap is c ∓ r·|(a, b)|.
    const double slope = std::hypot(a_, b_);
    if (on_arc(down_, t0, t1)) range.least = std::min(range.least, c_ - r1 * slope);
    if (on_arc(up_, t0, t1)) range.greatest = std::max(range.greatest, c_ + r1 * slope);
    return range;
  }

 private:
  // Whether the direction at angle ts (in (−π, π]) lies on the arc [t0, t1].
  static bool on_arc(double ts, double t0, double t1) {
    const double two_pi = 2.0 * std::numbers::pi;
    while (ts < t0) ts += two_pi;
    while (ts - two_pi >= t0) ts -= two_pi;
    return ts <= t1;
  }
  double c_, a_, b_;
  bool tilted_;
  double down_, up_;
};

// Calls integrate(std::bool_constant<gradients>): one instantiation per case, so the
// residual-only sums carry no test for the gradients in their inner loops.
template <class Integrate>
void with_gradients(bool gradients, const Integrate& integrate) {
  if (gradients)
    integrate(std::true_type{});
  else
    integrate(std::false_type{});
}

}  // namespace

void BearingModel::assemble_film_loads(std::span<const double> u, const Film& film, Assembler& a,
                                       FilmTotals& tot) const {
  const bool structural = a.mode() == Assembler::Mode::structure;
  const bool jac = a.wants_jacobian();
  const FilmMesh& m = film.mesh;
  const int nr = m.radial_nodes(), nt = m.circumferential_nodes();
  const GapPlane gap_plane = film.plane(position(u));
  const std::array<Index, 3> rigid_cols = film.rigid_columns();
  // film.gap_gradient(x, y) = g ⊙ (1, y, −x): the gap's slopes per unit moment arm.
  const std::array<double, 3> g{film.gap_gradient(0.0, 1.0)[0], film.gap_gradient(0.0, 1.0)[1],
                                film.gap_gradient(-1.0, 0.0)[2]};
  const bool hydro = film.pressure_offset >= 0;
  const bool heat = film.sliding && scene_.effects.thermal;
  const bool contact = contact_ != nullptr;
  const double omega = film.sliding ? scene_.operating.speed : 0.0;
  const double cutoff = contact_cutoff_;
  const PlaneOverCells plane(gap_plane.c, gap_plane.a, gap_plane.b);
  // Angles of nodes and of the rule's points within a cell: every Gauss point's
  // cos/sin follows by the addition theorem, without calling sincos per point.
  std::vector<double> cos_node(nt + 1), sin_node(nt + 1);
  for (int j = 0; j <= nt; ++j) {
    cos_node[j] = std::cos(m.angle(j));
    sin_node[j] = std::sin(m.angle(j));
  }
  auto rule_angles = [&](const GaussRule& rule, std::vector<double>& cq, std::vector<double>& sq) {
    for (double t : rule.points) {
      cq.push_back(std::cos(t * m.dtheta()));
      sq.push_back(std::sin(t * m.dtheta()));
    }
  };
  std::vector<double> cos_c, sin_c, cos_s, sin_s, cos_f, sin_f;
  rule_angles(contact_rule_, cos_c, sin_c);
  rule_angles(smooth_rule_, cos_s, sin_s);
  rule_angles(flat_contact_rule_, cos_f, sin_f);
  const bool flat_rule_is_cheaper = flat_contact_rule_.points.size() < contact_rule_.points.size();
  // A Gauss point (gs, gt) of cell (i, j): local coordinates, position, weight r dr dθ.
  struct Point { double s, t, r, x, y, w; };
  auto point = [&](const GaussRule& rule, const std::vector<double>& cq, const std::vector<double>& sq, int i,
                   int j, std::size_t gs, std::size_t gt) {
    const double s = rule.points[gs], r = m.radius(i) + s * m.dr();
    return Point{s, rule.points[gt], r, r * (cos_node[j] * cq[gt] - sin_node[j] * sq[gt]),
                 r * (sin_node[j] * cq[gt] + cos_node[j] * sq[gt]),
                 rule.weights[gs] * rule.weights[gt] * r * m.dr() * m.dtheta()};
  };

  // The contact rule's points of one cell within the cutoff, their gaps and pressures.
  std::vector<Point> contact_points;
  std::vector<double> contact_h;
  std::vector<ValueSlope> contact_p;

  // Rows of the rigid-body balance this film loads (eqs [34]-[37]): the washer sees
  // film 1 from below (+) and film 2 from above (−); the gear sees film 2 (+).
  const double f_ref = load_, m_ref = load_ * scene_.washer.outer_radius;
  struct RowSign { Index row; double force, mx, my; };
  std::vector<RowSign> rows;
  if (film.number == 1) {
    rows = {{rigid_offset_ + 0, 1.0 / f_ref, 0, 0}, {rigid_offset_ + 1, 0, 1.0 / m_ref, 0},
            {rigid_offset_ + 2, 0, 0, 1.0 / m_ref}};
  } else {
    rows = {{rigid_offset_ + 0, -1.0 / f_ref, 0, 0}, {rigid_offset_ + 1, 0, -1.0 / m_ref, 0},
            {rigid_offset_ + 2, 0, 0, -1.0 / m_ref}, {rigid_offset_ + 3, 1.0 / f_ref, 0, 0}};
  }

  // The smooth rule's points of one cell: viscosity temperature, gap, and their kernels.
  const std::size_t smooth_points = smooth_rule_.points.size();
  std::vector<double> point_t(smooth_points * smooth_points), point_h(point_t.size());
  std::vector<ValueSlope> point_mu(point_t.size()), point_gap(point_t.size());

  // Node viscosity temperatures and their gradients, computed once per node.
  std::vector<double> node_t(m.node_count());
  for (int n = 0; n < m.node_count(); ++n) node_t[n] = apply(viscosity_temperature_form(film, n), u);
  // Thermal deformation (film_shape.cpp): the gap is the plane plus the bilinear
  // interpolation of the node shapes δ; the sliding film's contact force has its own row
  // when f depends on it (empirical law), because every δ moves it.
  const std::vector<double> node_delta = node_shapes(u, film);
  const bool deformed = !node_delta.empty();
  const Index force_row = film.sliding ? contact_force_offset_ : -1;

  if (film.sliding) {
    tot.contact_power.assign(m.node_count(), 0.0);
    tot.contact_power_rigid.assign(m.node_count(), {0.0, 0.0, 0.0});
  }

  for (int i = 0; i < nr - 1; ++i) {
    for (int j = 0; j < nt; ++j) {
      const std::array<int, 4> ci{i, i + 1, i, i + 1};
      const std::array<int, 4> cj{j, j, j + 1, j + 1};
      std::array<int, 4> node;
      std::array<double, 4> p_node{}, t_node{}, d_node{};
      std::array<Index, 4> p_col{-1, -1, -1, -1};
      for (int k = 0; k < 4; ++k) {
        node[k] = m.node(ci[k], cj[k]);
        t_node[k] = node_t[node[k]];
        if (deformed) d_node[k] = node_delta[std::size_t(node[k])];
        p_col[k] = film.pressure_column(ci[k], cj[k]);
        if (p_col[k] >= 0) p_node[k] = p_ref_ * u[p_col[k]];
      }
      const double r0 = m.radius(i), r1 = m.radius(i + 1);
      const double t0 = m.angle(j), t1 = t0 + m.dtheta();
      GapRange gap_range = contact ? plane.range(r0, r1, t0, t1, cos_node[j], sin_node[j], cos_node[j + 1],
                                                 sin_node[j + 1])
                                   : GapRange{};
      // A bilinear shape stays within its corners' values.
      if (deformed) {
        gap_range.least += *std::min_element(d_node.begin(), d_node.end());
        gap_range.greatest += *std::max_element(d_node.begin(), d_node.end());
      }
      const bool near_contact = contact && (structural || gap_range.least < cutoff);

      // Local accumulators: value, d/d(rigid 3), d/d(corner pressure 4), d/d(corner T 4).
      // Rigid-body gradients are gathered against the moment arms a = (1, y, −x) of
      // (F, Mx, My): the gap gradient is dh = g ⊙ a (gap_gradient), so every integral
      // of f·dh is g ⊙ (integral of f·a), and g is applied once per cell.
      std::array<double, 3> load_val{};  // F, Mx, My
      std::array<std::array<double, 3>, 3> load_rigid{};  // against the arms until scaled by g
      std::array<std::array<double, 4>, 3> load_p{};
      std::array<double, 4> vheat{};
      std::array<std::array<double, 3>, 4> vheat_rigid{};  // against the arms until scaled by g
      std::array<std::array<double, 4>, 4> vheat_t{};
      // The same against the corner shapes δ_k (thermal deformation).
      std::array<std::array<double, 4>, 3> load_shape{};
      std::array<std::array<double, 4>, 4> vheat_shape{};
      std::array<std::array<double, 4>, 4> power_shape{};  // friction power per corner, against δ
      double load_val_contact = 0;            // the cell's contact force
      std::array<double, 3> contact_rigid{};  // its gradient against the arms

      // Contact: the high-order rule where contact can exist (elsewhere p_c < 1e-20 p(0),
      // whose force is below 1e-12 of any load: skipping is invisible to Newton).
      if (near_contact) {
        // Σ w p_c a, Σ w p_c' a aᵀ (symmetric: 00 01 02 11 12 22), and the friction power
        // per corner node with its gradient against the arms, added to the film once.
        std::array<double, 3> force{};
        std::array<double, 6> stiffness{};
        double torque = 0;
        std::array<double, 4> power{};
        std::array<std::array<double, 3>, 4> power_rigid{};
        // Where the pressure varies across the cell by less than a factor e^½ the
        // integrand is nearly polynomial and the flat rule (6 × 6 by default,
        // mesh.flat_contact_quadrature) integrates it to rounding: the n-point rule's
        // error is (n!)⁴/((2n+1)((2n)!)³) times the 2n-th derivative, and with ln p
        // changing by λ ≤ ½ across the cell and the cubic weights (r, moment arms,
        // hats) the 12th derivative is below 3, so the error is below 1e-15 of the
        // cell's contact force. On the paper's mesh below distress the film that
        // carries the load by contact (film 2) is nearly parallel, and all its cells are
        // flat: 36 points each instead of 64. (p(least) > 0 within the cutoff, so a
        // greatest gap where p underflows to 0 is never flat.)
        const bool flat = !structural && flat_rule_is_cheaper &&
                          contact_->pressure(gap_range.least).value <=
                              std::exp(0.5) * contact_->pressure(gap_range.greatest).value;
        const GaussRule& rule = flat ? flat_contact_rule_ : contact_rule_;
        const std::vector<double>& cos_r = flat ? cos_f : cos_c;
        const std::vector<double>& sin_r = flat ? sin_f : sin_c;
        // The cell's rule at the points within the cutoff (beyond it p < 1e-20 p(0),
        // above), their pressures as one batch (vectorized).
        contact_points.clear();
        contact_h.clear();
        for (std::size_t gs = 0; gs < rule.points.size(); ++gs) {
          for (std::size_t gt = 0; gt < rule.points.size(); ++gt) {
            const Point pt = point(rule, cos_r, sin_r, i, j, gs, gt);
            double h = gap_plane.at(pt.x, pt.y);
            if (deformed)
              h += (1 - pt.s) * (1 - pt.t) * d_node[0] + pt.s * (1 - pt.t) * d_node[1] +
                   (1 - pt.s) * pt.t * d_node[2] + pt.s * pt.t * d_node[3];
            if (h > cutoff) continue;
            contact_points.push_back(pt);
            contact_h.push_back(h);
          }
        }
        contact_p.resize(contact_h.size());
        contact_->pressure(contact_h, contact_p);
        // The same sums with and without the gradients (a residual alone, as IDA's
        // Newton iterations ask for most of the time, needs none of them).
        auto integrate = [&]<bool gradients>(std::bool_constant<gradients>) {
          for (std::size_t q = 0; q < contact_points.size(); ++q) {
            const auto [s, tt, r, x, y, w] = contact_points[q];
            const ValueSlope v = contact_p[q];
            const double f = w * v.value, k = w * v.slope;
            force[0] += f;
            force[1] += f * y;
            force[2] -= f * x;
            if constexpr (gradients) {
              stiffness[0] += k;
              stiffness[1] += k * y;
              stiffness[2] -= k * x;
              stiffness[3] += k * y * y;
              stiffness[4] -= k * x * y;
              stiffness[5] += k * x * x;
              if (deformed) {
                const std::array<double, 4> N{(1 - s) * (1 - tt), s * (1 - tt), (1 - s) * tt, s * tt};
                for (int l = 0; l < 4; ++l) {
                  load_shape[0][l] += k * N[l];
                  load_shape[1][l] += k * N[l] * y;
                  load_shape[2][l] -= k * N[l] * x;
                }
              }
            }
            if (!film.sliding) continue;
            // Friction opposes the sliding whichever way it goes: its power and torque
            // take the speed's magnitude (the sign of ω only turns the Couette flow).
            const double v_slide = std::abs(omega) * r;
            torque += f * r;
            const std::array<double, 4> N{(1 - s) * (1 - tt), s * (1 - tt), (1 - s) * tt, s * tt};
            for (int n = 0; n < 4; ++n) {
              const double nv = N[n] * v_slide;
              power[n] += f * nv;
              if constexpr (gradients) {
                const double kn = k * nv;
                power_rigid[n][0] += kn;
                power_rigid[n][1] += kn * y;
                power_rigid[n][2] -= kn * x;
                if (deformed)
                  for (int l = 0; l < 4; ++l) power_shape[n][l] += kn * N[l];
              }
            }
          }
        };
        with_gradients(jac || structural, integrate);
        const std::array<std::array<double, 3>, 3> arms{{{stiffness[0], stiffness[1], stiffness[2]},
                                                         {stiffness[1], stiffness[3], stiffness[4]},
                                                         {stiffness[2], stiffness[4], stiffness[5]}}};
        for (int qd = 0; qd < 3; ++qd) {
          load_val[qd] += force[qd];
          for (int d = 0; d < 3; ++d) load_rigid[qd][d] += arms[qd][d];
        }
        load_val_contact = force[0];
        contact_rigid = arms[0];
        tot.contact_force += force[0];
        for (int d = 0; d < 3; ++d) tot.contact_force_rigid[d] += g[d] * arms[0][d];

        if (film.sliding) {
          tot.contact_torque_per_f += torque;
          for (int n = 0; n < 4; ++n) {
            tot.contact_power[node[n]] += power[n];
            for (int d = 0; d < 3; ++d) tot.contact_power_rigid[node[n]][d] += g[d] * power_rigid[n][d];
          }
        }
      }

      // Every cell's terms, zero or not, so that every pass adds the same entries in the
      // same order (the slot tape, sparse_assembly.h).
      if (deformed && film.sliding && contact)
        for (int n = 0; n < 4; ++n)
          for (int l = 0; l < 4; ++l) tot.contact_power_shape.push_back({node[n], node[l], power_shape[n][l]});

      // Fluid pressure (bilinear between nodes) and viscous shear: one fixed rule on
      // every cell, so the residual stays smooth as contact comes and goes. Viscosity
      // and average gap at the cell's points first, as one batch each (vectorized).
      if (film.sliding) {
        for (std::size_t gs = 0, q = 0; gs < smooth_points; ++gs) {
          for (std::size_t gt = 0; gt < smooth_points; ++gt, ++q) {
            const auto [s, tt, r, x, y, w] = point(smooth_rule_, cos_s, sin_s, i, j, gs, gt);
            const std::array<double, 4> N{(1 - s) * (1 - tt), s * (1 - tt), (1 - s) * tt, s * tt};
            point_t[q] = 0;
            for (int k = 0; k < 4; ++k) point_t[q] += N[k] * t_node[k];
            point_h[q] = gap_plane.at(x, y);
            if (deformed)
              for (int k = 0; k < 4; ++k) point_h[q] += N[k] * d_node[k];
          }
        }
        viscosity(point_t, point_mu);
        average_gap(point_h, film.sigma, point_gap);
      }
      auto integrate_smooth = [&]<bool gradients>(std::bool_constant<gradients>) {
        for (std::size_t gs = 0; (hydro || film.sliding) && gs < smooth_points; ++gs) {
          for (std::size_t gt = 0; gt < smooth_points; ++gt) {
            const std::size_t q = gs * smooth_points + gt;
            const auto [s, tt, r, x, y, w] = point(smooth_rule_, cos_s, sin_s, i, j, gs, gt);
            const std::array<double, 4> N{(1 - s) * (1 - tt), s * (1 - tt), (1 - s) * tt, s * tt};
            if (hydro) {
              double p = 0;
              for (int k = 0; k < 4; ++k) p += N[k] * p_node[k];
              const std::array<double, 3> arm{1.0, y, -x};
              for (int qd = 0; qd < 3; ++qd) {
                load_val[qd] += w * p * arm[qd];
                if constexpr (gradients)
                  for (int k = 0; k < 4; ++k) load_p[qd][k] += w * N[k] * p_ref_ * arm[qd];
              }
              tot.fluid_force += w * p;
            }
            if (!film.sliding) continue;
            const double v_slide = std::abs(omega) * r;
            const ValueSlope mu = point_mu[q];
            // Shear acts over the average gap, which stays positive where h closes (docs/physics.md 3, 6).
            const ValueSlope gap = point_gap[q];
            const double tau = mu.value * v_slide / gap.value;
            tot.viscous_torque += w * tau * r;
            const double qv = tau * v_slide;  // μ V² / h̄T
            tot.viscous_heat += w * qv;
            const double dqv_dh = -qv / gap.value * gap.slope;
            const double dqv_dt = mu.slope * v_slide * v_slide / gap.value;
            for (int k = 0; k < 4; ++k) {
              const double wn = w * N[k];
              vheat[k] += wn * qv;
              if constexpr (gradients) {
                const double q = wn * dqv_dh;
                vheat_rigid[k][0] += q;
                vheat_rigid[k][1] += q * y;
                vheat_rigid[k][2] -= q * x;
                for (int l = 0; l < 4; ++l) vheat_t[k][l] += wn * dqv_dt * N[l];
                if (deformed)
                  for (int l = 0; l < 4; ++l) vheat_shape[k][l] += q * N[l];
              }
            }
          }
        }
      };
      with_gradients(jac || structural, integrate_smooth);

      // Scatter the cell's loads into the rigid-body rows.
      for (const RowSign& rs : rows) {
        const std::array<double, 3> coef{rs.force, rs.mx, rs.my};
        for (int qd = 0; qd < 3; ++qd) {
          if (coef[qd] == 0.0) continue;
          a.add_residual(rs.row, coef[qd] * load_val[qd]);
          if (!jac) continue;
          for (int d = 0; d < 3; ++d) a.add_derivative(rs.row, rigid_cols[d], coef[qd] * g[d] * load_rigid[qd][d]);
          for (int k = 0; k < 4; ++k) a.add_derivative(rs.row, p_col[k], coef[qd] * load_p[qd][k]);
          if (deformed)
            for (int k = 0; k < 4; ++k)
              a.add_form(rs.row, coef[qd] * load_shape[qd][k], shape_form(film, node[k]));
        }
      }
      // The sliding film's contact force into its own row (F_c/F_ref, film_shape.cpp).
      if (force_row >= 0) {
        a.add_residual(force_row, load_val_contact / contact_force_ref_);
        if (jac) {
          for (int d = 0; d < 3; ++d)
            a.add_derivative(force_row, rigid_cols[d], g[d] * contact_rigid[d] / contact_force_ref_);
          for (int k = 0; k < 4; ++k)
            a.add_form(force_row, load_shape[0][k] / contact_force_ref_, shape_form(film, node[k]));
        }
      }
      // Viscous heat into the film-node rows (friction heat is added once f is known).
      if (heat) {
        for (int k = 0; k < 4; ++k) {
          const Index row = film.temperature_row(node[k]);
          const double sc = film_row_scale_[film.number - 1][node[k]];
          a.add_residual(row, sc * vheat[k]);
          if (!jac) continue;
          for (int d = 0; d < 3; ++d) a.add_derivative(row, rigid_cols[d], sc * g[d] * vheat_rigid[k][d]);
          for (int l = 0; l < 4; ++l) a.add_form(row, sc * vheat_t[k][l], viscosity_temperature_form(film, node[l]));
          if (deformed)
            for (int l = 0; l < 4; ++l) a.add_form(row, sc * vheat_shape[k][l], shape_form(film, node[l]));
        }
      }
    }
  }

  if (!film.sliding) return;
  // Boundary friction f·p_cont (docs/physics.md section 6). The empirical law [18] depends on
  // the film's total contact force, so f couples every heat row to the rigid body.
  if (scene_.friction.law == FrictionLaw::constant) {
    tot.friction_coefficient = scene_.friction.coefficient;
    tot.friction_slope = 0.0;
  } else {
    // With thermal deformation the law reads the contact-force unknown (equal to the
    // integral at a solution), so that its slope is one column of every heat row.
    const double contact_force = force_row >= 0 ? u[std::size_t(force_row)] * contact_force_ref_ : tot.contact_force;
    const FrictionLawResult fr = empirical_friction(contact_force);
    tot.friction_coefficient = fr.coefficient;
    tot.friction_slope = fr.slope;
    tot.friction_clamped = fr.clamped;
  }
  for (double cp : tot.contact_power) tot.friction_heat += tot.friction_coefficient * cp;
  if (!heat) return;
  for (int n = 0; n < m.node_count(); ++n) {
    const Index row = film.temperature_row(n);
    const double sc = film_row_scale_[film.number - 1][n];
    a.add_residual(row, sc * tot.friction_coefficient * tot.contact_power[n]);
    if (!jac) continue;
    const double slope_rigid = force_row >= 0 ? 0.0 : tot.friction_slope;
    for (int d = 0; d < 3; ++d)
      a.add_derivative(row, rigid_cols[d],
                       sc * (tot.friction_coefficient * tot.contact_power_rigid[n][d] +
                             slope_rigid * tot.contact_power[n] * tot.contact_force_rigid[d]));
    if (force_row >= 0)
      a.add_derivative(row, force_row, sc * tot.friction_slope * contact_force_ref_ * tot.contact_power[n]);
  }
  if (!jac) return;
  for (const ShapeTerm& term : tot.contact_power_shape)
    a.add_form(film.temperature_row(term.node),
               film_row_scale_[film.number - 1][term.node] * tot.friction_coefficient * term.coefficient,
               shape_form(film, term.corner));
}

}  // namespace twb
