// Asperity contact on one cell of a film (docs/physics.md sections 4, 6): the contact
// force and its moments on the high-order rule at the points within the cutoff, and on
// the sliding film the friction power per corner node (friction heat is f times it,
// added once the film's total contact force sets f: FilmLoadPass::friction). Where the
// sliding film's faces run in (section 20), the summits at a point are the population
// scaled by k = σ/σ0 of its Rqs ([W8]), with p's slopes in each corner's Rqs.
#include <cmath>

#include "model/film_load_pass.h"

namespace twb {
namespace {

// Each corner's share ∫ p_c·N_k dA of a point's contact force f (its slope k = w·p_c'),
// the load on the washer's plate (film_loads.cpp), with its slopes in the arms, the corner
// shapes and, where the faces run in, the corners' Rqs (w·∂p_c/∂Rq of each face).
template <bool gradients>
void add_corner_forces(CellLoads& l, const std::array<double, 4>& N, double x, double y, double f, double k, double w,
                       bool runs_in, const std::array<double, 2>& by_rq) {
  for (int n = 0; n < 4; ++n) {
    l.corner_force[n] += f * N[n];
    if constexpr (!gradients) continue;
    const double kn = k * N[n];
    l.corner_force_rigid[n][0] += kn;
    l.corner_force_rigid[n][1] += kn * y;
    l.corner_force_rigid[n][2] -= kn * x;
    for (int m = 0; m < 4; ++m) l.corner_force_shape[n][m] += kn * N[m];
    if (!runs_in) continue;
    for (int m = 0; m < 4; ++m) {
      l.corner_force_rest[n][m] += w * by_rq[0] * N[n] * N[m];
      l.corner_force_turn[n][m] += w * by_rq[1] * N[n] * N[m];
    }
  }
}

}  // namespace

void FilmLoadPass::contact_on_cell(const FilmCell& cell, CellLoads& l, FilmTotals& tot) {
  const StatisticalContact& asperities = *model.contact();
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
  const bool runs_in = roughness.varies();
  // (The flat rule's test reads one population: not where the summits vary over the cell.)
  const bool flat = !structural && !runs_in && flat_rule_is_cheaper &&
                    asperities.pressure(cell.gap.range.least).value <=
                        std::exp(0.5) * asperities.pressure(cell.gap.range.greatest).value;
  const CellRule& rule = flat ? flat_rule : contact_rule;
  // The cell's rule at the points within the cutoff (beyond it p < 1e-20 p(0),
  // above), their pressures as one batch (vectorized).
  contact_points.clear();
  contact_h.clear();
  for (std::size_t gs = 0; gs < rule.size(); ++gs) {
    for (std::size_t gt = 0; gt < rule.size(); ++gt) {
      const CellPoint pt = rule.point(cell.i, cell.j, gs, gt);
      const double h = gap.at(cell.gap, pt.s, pt.t, pt.x, pt.y);
      if (h > cutoff) continue;
      contact_points.push_back(pt);
      contact_h.push_back(h);
    }
  }
  contact_p.resize(contact_h.size());
  if (!runs_in) {
    asperities.pressure(contact_h, contact_p);
  } else {
    // p(h, k) with k = σ/σ0 at the point, its Rqs bilinear in the corners' (film_roughness.h).
    const ScaledContact& scaled = *model.scaled_contact();
    const double sigma0 = roughness.uniform().sigma;
    contact_by_rq.resize(contact_h.size());
    for (std::size_t q = 0; q < contact_h.size(); ++q) {
      const PointRoughness pr = roughness.in_cell(cell.node, contact_points[q].s, contact_points[q].t);
      const ScaledContact::Pressure p = scaled.pressure(contact_h[q], pr.sigma / sigma0);
      contact_p[q] = {p.value, p.dh};
      contact_by_rq[q] = {p.dk * pr.sigma_by_rest / sigma0, p.dk * pr.sigma_by_turn / sigma0};
    }
  }
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
        if (shaped) {
          const std::array<double, 4> N = corner_hats(s, tt);
          for (int m = 0; m < 4; ++m) {
            l.load_shape[0][m] += k * N[m];
            l.load_shape[1][m] += k * N[m] * y;
            l.load_shape[2][m] -= k * N[m] * x;
          }
        }
        if (runs_in) {
          const std::array<double, 4> N = corner_hats(s, tt);
          const double kr = w * contact_by_rq[q][0], kt = w * contact_by_rq[q][1];
          for (int m = 0; m < 4; ++m) {
            l.load_rest[0][m] += kr * N[m];
            l.load_rest[1][m] += kr * N[m] * y;
            l.load_rest[2][m] -= kr * N[m] * x;
            l.load_turn[0][m] += kt * N[m];
            l.load_turn[1][m] += kt * N[m] * y;
            l.load_turn[2][m] -= kt * N[m] * x;
          }
        }
      }
      if (plate) {
        const std::array<double, 2> by_rq = runs_in ? contact_by_rq[q] : std::array<double, 2>{};
        add_corner_forces<gradients>(l, corner_hats(s, tt), x, y, f, k, w, runs_in, by_rq);
      }
      if (!film.sliding) continue;
      // Friction opposes the sliding whichever way it goes: its power and torque
      // take the speed's magnitude (the sign of ω only turns the Couette flow).
      const double v_slide = std::abs(omega) * r;
      torque += f * r;
      const std::array<double, 4> N = corner_hats(s, tt);
      for (int n = 0; n < 4; ++n) {
        const double nv = N[n] * v_slide;
        power[n] += f * nv;
        if constexpr (gradients) {
          const double kn = k * nv;
          power_rigid[n][0] += kn;
          power_rigid[n][1] += kn * y;
          power_rigid[n][2] -= kn * x;
          if (shaped)
            for (int m = 0; m < 4; ++m) l.power_shape[n][m] += kn * N[m];
          if (runs_in)
            for (int m = 0; m < 4; ++m) {
              l.power_rest[n][m] += w * contact_by_rq[q][0] * nv * N[m];
              l.power_turn[n][m] += w * contact_by_rq[q][1] * nv * N[m];
            }
        }
      }
    }
  };
  with_gradients(jac || structural, integrate);
  const std::array<std::array<double, 3>, 3> arms{{{stiffness[0], stiffness[1], stiffness[2]},
                                                   {stiffness[1], stiffness[3], stiffness[4]},
                                                   {stiffness[2], stiffness[4], stiffness[5]}}};
  for (int qd = 0; qd < 3; ++qd) {
    l.load_val[qd] += force[qd];
    for (int d = 0; d < 3; ++d) l.load_rigid[qd][d] += arms[qd][d];
  }
  l.contact_force = force[0];
  l.contact_rigid = arms[0];
  tot.contact_force += force[0];
  for (int d = 0; d < 3; ++d) tot.contact_force_rigid[d] += g[d] * arms[0][d];
  if (!film.sliding) return;
  tot.contact_torque_per_f += torque;
  for (int n = 0; n < 4; ++n) {
    tot.contact_power[cell.node[n]] += power[n];
    for (int d = 0; d < 3; ++d) tot.contact_power_rigid[cell.node[n]][d] += g[d] * power_rigid[n][d];
  }
}

}  // namespace twb
