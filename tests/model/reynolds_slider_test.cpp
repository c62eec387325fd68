// The Reynolds finite volumes (docs/physics.md section 3) against Reynolds' infinitely wide
// inclined slider: pad length L, outlet film h_o, inlet film K h_o, one surface sliding
// at U, ambient pressure at both ends; load per unit width
//   W' = 6 μ U L² / (h_o² (K − 1)²) · [ln K − 2 (K − 1)/(K + 1)].
//
// The limit. The operator slides along θ, is periodic in θ and holds p = 0 at both
// radii, so the slider is a sector pad: H(θ) falls linearly from K H_o to H_o over the
// pad angle Θ, then a deep groove (H = 1000 H_o) leads to the next identical pad. The
// film grows in proportion to the radius, h(r, θ) = r H(θ). That choice makes the limit
// exact: for h = r H(θ) the polar equation [1]
//   (1/r) ∂r(r g ∂r p) + (1/r²) ∂θ(g ∂θ p) = (ω/2) ∂θ h,   g = h³/(12 μ),
// has r-independent solutions p = P(θ), with (H³ P')' = 6 μ ω H' — at every radius
// exactly the 1-D slider with U = ω r, L = r Θ, h_o = r H_o (no curvature correction).
// The discrete operator shares this: with p independent of r every radial flux
// vanishes and each circumferential balance is r_i²Δr times the same 1-D balance.
// The groove, whose conductance is 1e9 times the pad's, holds both pad ends at
// ambient (1-D estimate of the residual groove pressure: (L_g/L)(H_o/H_g)² of the pad
// pressure scale, ~1e-6 here).
//
// What departs from the 1-D slider is the side leakage at the two radii: p = 0 there
// instead of P(θ). Its correction solves the homogeneous equation and decays into the
// film exponentially, roughly like exp(−π d/L(r)) with the distance d from the edge, so
// the infinitely wide slider is the pressure on the mid radius R as B/L → ∞,
// B = r_o − r_i (B ≫ L; the opposite, L ≫ B, would be the short bearing). The test
// measures W' = R ∫ p(R, θ) dθ over a pad and lets B/L grow (more, shorter pads round
// the annulus) while refining the grid. (With B/L ≈ 10 and 96, 192 cells per pad the
// error falls 1.9e-4 → 4.9e-5, second order towards 3e-6: the limit is Reynolds' value.)
//
// Cavitation: a converging pad has p > 0 everywhere and the groove sits at ambient,
// so the Reynolds condition is inactive and the linear system w(p) = 0 is the model's
// problem; the test checks that no node goes below −1e-4 of the peak pressure.
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "twb/model/film_mesh.h"
#include "model/reynolds_operator.h"

namespace twb {
namespace {

struct Slider {
  double mid_radius = 10e-3;              // R, m
  double width = 10e-3;                   // B = r_o − r_i, m
  double h_out = 10e-6;                   // h_o at R, m
  double k = 2.0;                         // inlet / outlet film
  double groove = 1000.0;                 // groove film / h_o
  double mu = 0.01, omega = 100.0;        // Pa s, rad/s

  // Reynolds' load per unit width of the pad on the mid radius.
  double analytic_load(double pad_angle) const {
    const double u = omega * mid_radius, l = mid_radius * pad_angle;
    return 6.0 * mu * u * l * l / (h_out * h_out * (k - 1) * (k - 1)) * (std::log(k) - 2.0 * (k - 1) / (k + 1));
  }
};

struct Setting {
  int pads, pad_cells, groove_cells, radial_nodes;
};

struct SliderResult {
  double width_over_length;  // B / L on the mid radius
  double load, analytic;     // per unit width, N/m
  double lowest_pressure;    // min p / max p
};

SliderResult solve(const Slider& s, const Setting& set) {
  const int period = set.pad_cells + set.groove_cells, nt = set.pads * period;
  const FilmMesh mesh(s.mid_radius - 0.5 * s.width, s.mid_radius + 0.5 * s.width, set.radial_nodes, nt);
  const ReynoldsOperator op(mesh);
  const double groove_angle = set.groove_cells * mesh.dtheta(), pad_angle = set.pad_cells * mesh.dtheta();
  const double big_h = s.h_out / s.mid_radius;  // H_o

  // H(θ): groove, then the pad converging in the sliding direction (+θ). Faces sit at
  // mid-cell, never on the steps.
  auto shape = [&](double th) {
    const double phi = th - std::floor(th / (groove_angle + pad_angle)) * (groove_angle + pad_angle);
    if (phi < groove_angle) return s.groove * big_h;
    return big_h * (s.k - (s.k - 1) * (phi - groove_angle) / pad_angle);
  };
  const auto faces = std::size_t(op.face_count());
  std::vector<double> g(faces), carried(faces);
  op.for_each_face([&](const ReynoldsFace& f) {
    const double h = f.r * shape(f.theta);
    g[f.index] = h * h * h / (12.0 * s.mu);
    carried[f.index] = h;
  });

  const int n = op.interior_count();
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& e : op.pressure_coefficients(g)) entries.emplace_back(e.row, e.col, e.value);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  const std::vector<double> w0 = op.net_outflow(s.omega, g, carried, std::vector<double>(std::size_t(n), 0.0));
  Eigen::VectorXd rhs(n);
  for (int k = 0; k < n; ++k) rhs[k] = -w0[k];
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(a);
  EXPECT_EQ(lu.info(), Eigen::Success);
  const Eigen::VectorXd p = lu.solve(rhs);

  // Load per unit width on the mid radius, trapezoidal over each pad's nodes (the
  // integral of the piecewise-linear pressure), averaged over the identical pads.
  const int mid = (set.radial_nodes - 1) / 2;
  double load = 0.0;
  for (int pad = 0; pad < set.pads; ++pad) {
    const int first = pad * period + set.groove_cells;
    for (int j = first; j <= first + set.pad_cells; ++j) {
      const double weight = (j == first || j == first + set.pad_cells) ? 0.5 : 1.0;
      load += weight * p[op.interior_index(mid, j)] * mesh.dtheta() * s.mid_radius;
    }
  }
  load /= set.pads;
  return {s.width / (s.mid_radius * pad_angle), load, s.analytic_load(pad_angle), p.minCoeff() / p.maxCoeff()};
}

TEST(ReynoldsSlider, WidePadLoadApproachesReynoldsInclinedSlider) {
  const Slider s;
  const std::vector<Setting> settings{{5, 8, 2, 9}, {10, 16, 4, 17}, {20, 32, 8, 33}, {30, 48, 12, 49}};
  std::printf("  pads  pad cells  Nr   B/L    W' (N/m)     analytic     error\n");
  double previous = INFINITY;
  for (const Setting& set : settings) {
    const SliderResult r = solve(s, set);
    const double error = std::abs(r.load / r.analytic - 1.0);
    std::printf("  %4d  %9d  %3d  %4.2f  %.6e  %.6e  %.2e  (min p / max p %.1e)\n", set.pads, set.pad_cells,
                set.radial_nodes, r.width_over_length, r.load, r.analytic, error, r.lowest_pressure);
    EXPECT_LT(error, previous) << "the error must fall as B/L grows and the grid refines";
    EXPECT_GT(r.lowest_pressure, -1e-4) << "the pad would cavitate: the linear solve would not be the model's problem";
    previous = error;
  }
  EXPECT_LT(previous, 1e-2);
}

}  // namespace
}  // namespace twb
