// The fluid film on one cell (docs/physics.md sections 3, 6): the pressure's force and
// moments (bilinear between the nodes) and, on the sliding film, viscous shear over the
// average gap: its torque and its heat spread onto the corner nodes with the hats. One
// fixed rule on every cell, so the residual stays smooth as contact comes and goes.
#include <cmath>

#include "model/film_load_pass.h"
#include "physics/average_gap.h"

namespace twb {

void FilmLoadPass::fluid_on_cell(const FilmCell& cell, CellLoads& l, FilmTotals& tot) {
  const std::size_t smooth_points = smooth_rule.size();
  // Viscosity and average gap at the cell's points first, as one batch each (vectorized).
  if (film.sliding) {
    for (std::size_t gs = 0, q = 0; gs < smooth_points; ++gs) {
      for (std::size_t gt = 0; gt < smooth_points; ++gt, ++q) {
        const auto [s, tt, r, x, y, w] = smooth_rule.point(cell.i, cell.j, gs, gt);
        const std::array<double, 4> N = corner_hats(s, tt);
        point_t[q] = 0;
        for (int k = 0; k < 4; ++k) point_t[q] += N[k] * cell.t_node[k];
        point_h[q] = gap.at(cell.gap, s, tt, x, y);
      }
    }
    model.viscosity(point_t, point_mu);
    if (!roughness.varies()) {
      average_gap(point_h, film.sigma, point_gap);
    } else {
      // The faces run in: σ at each point from its corners' Rqs (film_roughness.h).
      point_rough.resize(point_h.size());
      for (std::size_t gs = 0, q = 0; gs < smooth_points; ++gs)
        for (std::size_t gt = 0; gt < smooth_points; ++gt, ++q) {
          const auto [s, tt, r, x, y, w] = smooth_rule.point(cell.i, cell.j, gs, gt);
          point_rough[q] = roughness.in_cell(cell.node, s, tt);
          point_gap[q] = average_gap(point_h[q], point_rough[q].sigma);
        }
    }
  }
  const double p_ref = model.pressure_scale();
  auto integrate = [&]<bool gradients>(std::bool_constant<gradients>) {
    for (std::size_t gs = 0; (hydro || film.sliding) && gs < smooth_points; ++gs) {
      for (std::size_t gt = 0; gt < smooth_points; ++gt) {
        const std::size_t q = gs * smooth_points + gt;
        const auto [s, tt, r, x, y, w] = smooth_rule.point(cell.i, cell.j, gs, gt);
        const std::array<double, 4> N = corner_hats(s, tt);
        if (hydro) {
          double p = 0;
          for (int k = 0; k < 4; ++k) p += N[k] * cell.p_node[k];
          const std::array<double, 3> arm{1.0, y, -x};
          for (int qd = 0; qd < 3; ++qd) {
            l.load_val[qd] += w * p * arm[qd];
            if constexpr (gradients)
              for (int k = 0; k < 4; ++k) l.load_p[qd][k] += w * N[k] * p_ref * arm[qd];
          }
          tot.fluid_force += w * p;
          if (plate)
            for (int k = 0; k < 4; ++k) {
              l.corner_force[k] += w * p * N[k];
              if constexpr (gradients)
                for (int m = 0; m < 4; ++m) l.corner_force_p[k][m] += w * N[k] * N[m] * p_ref;
            }
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
          l.vheat[k] += wn * qv;
          if constexpr (gradients) {
            const double qn = wn * dqv_dh;
            l.vheat_rigid[k][0] += qn;
            l.vheat_rigid[k][1] += qn * y;
            l.vheat_rigid[k][2] -= qn * x;
            for (int m = 0; m < 4; ++m) l.vheat_t[k][m] += wn * dqv_dt * N[m];
            if (shaped)
              for (int m = 0; m < 4; ++m) l.vheat_shape[k][m] += qn * N[m];
            if (roughness.varies()) {
              const PointRoughness& pr = point_rough[q];
              const double by_sigma = -wn * qv / gap.value * average_gap_by_sigma(point_h[q], pr.sigma);
              for (int m = 0; m < 4; ++m) {
                l.vheat_rest[k][m] += by_sigma * pr.sigma_by_rest * N[m];
                l.vheat_turn[k][m] += by_sigma * pr.sigma_by_turn * N[m];
              }
            }
          }
        }
      }
    }
  };
  with_gradients(jac || structural, integrate);
}

}  // namespace twb
