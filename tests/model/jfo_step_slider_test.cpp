// The mass-conserving discretization (ReynoldsOperator's face flux with the upwind film
// content, docs/physics.md section 12) against the 1-D slider with a pocket, whose
// mass-conserving solution is known in closed form.
//
// The slider, sliding at U over a pad fed by a flooded groove at both ends (p = 0,
// θ = 1): a land of film h1 on [0, a], a pocket h2 > h1 on [a, b], a wedge closing from
// h1 to h0 < h1 on [b, L]. The land carries the flux q = U h1/2 at p = 0. At the
// diverging step the film ruptures, and the pocket is partly filled, θ = h1/h2, at p = 0;
// the wedge builds pressure, which pushes the reformation front x_r back into the
// pocket. From x_r on the film is full and carries the same flux (mass is conserved
// across the front), so p' = 6 μ U (h − h1)/h³ with p(x_r) = p(L) = 0:
//   (h2 − h1)/h2³ (b − x_r) = −I(L),  I(x) = ∫_b^x (h − h1)/h³ dx
//                          = (1/s)[(1/h − 1/h1) − (h1/2)(1/h² − 1/h1²)],  s = −h'.
// (The Reynolds condition instead floods the pocket, p > 0 only in the wedge.)
//
// The discrete film: one ring of the polar operator at radius R (x = R θ, U = ω R) with
// no radial flow (the radial faces' conductance 0), the pad's nodes unknown, the groove's
// held at p = 0, θ = 1; h at the face midpoints. Its equations are the model's: each
// node's flow balance, and p ≥ 0, θ ≤ 1 in Fischer–Burmeister form, solved by
// semismooth Newton. The upwind content resolves the reformation front to a cell: the
// test asks for the discrete front (the first full node after the pocket) within one
// cell of x_r, and for the load within the area a front misplaced by a cell can move,
// p'(x_r)·Δx² (the pressure rises from the front at p'(x_r) = 6 μ U (h2 − h1)/h2³),
// which also bounds the full film's second-order truncation here (it is far smaller:
// the errors are 1e-5 … 1e-6 of the load).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "model/reynolds_operator.h"

namespace twb {
namespace {

constexpr double kA = 0.5e-3, kB = 2.5e-3, kL = 5e-3;  // land, pocket end, pad end (m of arc)
// The ring holds exactly 12 pad lengths, so that every mesh puts nodes on the pad's ends.
constexpr double kMu = 0.05, kOmega = 500.0, kR = 12 * kL / (2 * std::numbers::pi);
constexpr double kH1 = 10e-6, kH2 = 20e-6, kH0 = 9e-6;

double gap(double x) {
  if (x < kA) return kH1;
  if (x < kB) return kH2;
  return kH1 - (kH1 - kH0) * (x - kB) / (kL - kB);
}

struct Analytic {
  double front, peak, load;  // x_r, max p, ∫ p dx over the pad
  double front_slope;        // p'(x_r)
};

Analytic analytic() {
  const double u = kOmega * kR, s = (kH1 - kH0) / (kL - kB);
  auto wedge = [&](double x) {
    const double h = gap(x);
    return (1 / s) * ((1 / h - 1 / kH1) - 0.5 * kH1 * (1 / (h * h) - 1 / (kH1 * kH1)));
  };
  const double rise = (kH2 - kH1) / (kH2 * kH2 * kH2);
  Analytic a;
  a.front = kB + wedge(kL) / rise;
  const double pb = 6 * kMu * u * rise * (kB - a.front);
  a.peak = pb;  // p rises through the pocket and falls in the wedge (h < h1)
  a.front_slope = 6 * kMu * u * rise;
  // ∫ p: a triangle-like ramp in the pocket, then pb + 6 μ U I(x) over the wedge
  // (Gauss–Legendre on 64 panels: I is smooth there).
  double wedge_integral = 0;
  const double xg[2] = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  const int panels = 64;
  for (int k = 0; k < panels; ++k) {
    const double x0 = kB + (kL - kB) * k / panels, x1 = kB + (kL - kB) * (k + 1) / panels;
    for (double g : xg) wedge_integral += 0.5 * (x1 - x0) * (pb + 6 * kMu * u * wedge(0.5 * (x0 + x1) + 0.5 * (x1 - x0) * g));
  }
  a.load = 0.5 * pb * (kB - a.front) + wedge_integral;
  return a;
}

struct Discrete {
  std::vector<double> x, p, theta;
  double load = 0;
};

Discrete solve(int nodes_per_pad) {
  const double dx = kL / nodes_per_pad;
  const int n = int(std::round(2 * std::numbers::pi * kR / dx));  // nodes round the ring
  const FilmMesh mesh(kR - 1e-4, kR + 1e-4, 3, n);
  const ReynoldsOperator op(mesh);
  // Pad nodes 1 … nodes_per_pad − 1 are unknown; node 0, the pad's end node and the
  // groove beyond are held flooded at ambient.
  const int m = nodes_per_pad - 1;
  auto unknown = [&](int j) { return j >= 1 && j <= m ? j - 1 : -1; };
  const double x_of = mesh.dtheta() * kR;  // arc per node (≈ dx)
  const double p_scale = 6 * kMu * kOmega * kR * kL / (kH1 * kH1);
  std::vector<double> p(m, 0.0), theta(m, 1.0);
  auto value = [&](const std::vector<double>& v, int j, double held) { const int k = unknown(mesh.wrap(j)); return k >= 0 ? v[k] : held; };
  for (int iteration = 0; iteration < 100; ++iteration) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2 * m, 2 * m);
    double flux_scale = 0;
    for (int j = 0; j < n; ++j) {
      const ReynoldsFace f = op.circumferential_face(1, j);
      const double xf = (j + 0.5) * x_of;
      const double h = xf < kL ? gap(xf) : 1e-3;  // the groove: deep
      const double g = h * h * h / (12 * kMu);
      const int up = ReynoldsOperator::upwind_node(f, kOmega);
      const int ju = up == f.a ? j : j + 1;
      const double th = value(theta, ju, 1.0);
      const ReynoldsFaceFlux q = ReynoldsOperator::flux(f, kOmega, g, th * h, value(p, j, 0.0), value(p, j + 1, 0.0));
      flux_scale = std::max(flux_scale, std::abs(q.dq_dcarried * h));
      for (const auto [node, sign] : f.ends()) {
        const int k = unknown(mesh.wrap(node == f.a ? j : j + 1));
        if (k < 0) continue;
        r[k] += sign * q.q;
        if (unknown(mesh.wrap(j)) >= 0) J(k, unknown(mesh.wrap(j))) += sign * q.dq_dpa * p_scale;
        if (unknown(mesh.wrap(j + 1)) >= 0) J(k, unknown(mesh.wrap(j + 1))) += sign * q.dq_dpb * p_scale;
        if (unknown(mesh.wrap(ju)) >= 0) J(k, m + unknown(mesh.wrap(ju))) += sign * q.dq_dcarried * h;
      }
    }
    r.head(m) /= flux_scale;
    J.topRows(m) /= flux_scale;
    for (int k = 0; k < m; ++k) {
      const double a = p[k] / p_scale, b = 1 - theta[k], norm = std::hypot(a, b);
      r[m + k] = a + b - norm;
      J(m + k, k) = (norm > 0 ? 1 - a / norm : 1 - std::sqrt(0.5)) / p_scale * p_scale;
      J(m + k, m + k) = -(norm > 0 ? 1 - b / norm : 1 - std::sqrt(0.5));
    }
    if (r.lpNorm<Eigen::Infinity>() < 1e-12) break;
    // Newton in the scaled pressure p̂ = p/p_scale and θ.
    const Eigen::VectorXd step = J.partialPivLu().solve(-r);
    for (int k = 0; k < m; ++k) {
      p[k] += step[k] * p_scale;
      theta[k] += step[m + k];
    }
  }
  Discrete d;
  d.x.resize(m);
  for (int k = 0; k < m; ++k) {
    d.x[k] = (k + 1) * x_of;
    d.load += p[k] * x_of;  // trapezoid: p = 0 at both pad ends
  }
  d.p = p;
  d.theta = theta;
  return d;
}

TEST(JfoStepSlider, MatchesTheMassConservingSolution) {
  const Analytic exact = analytic();
  ASSERT_GT(exact.front, kA);  // the front lies inside the pocket: the case is as described
  ASSERT_LT(exact.front, kB);
  for (const int nodes : {100, 200, 400}) {
    const Discrete d = solve(nodes);
    const double dx = kL / nodes;
    const double error = std::abs(d.load - exact.load);
    double front = 0;
    for (std::size_t k = 0; k < d.x.size() && front == 0; ++k)
      if (d.x[k] > kA && d.theta[k] > 1 - 1e-9) front = d.x[k];
    EXPECT_NEAR(front, exact.front, dx) << nodes << " nodes per pad";
    // In the pocket ahead of the front the film is exactly as full as the land feeds
    // it: θ = h1/h2 (the upwind transport is exact for a uniform film), p = 0.
    for (std::size_t k = 0; k < d.x.size(); ++k) {
      if (d.x[k] > kA + kL / nodes && d.x[k] < exact.front - 2 * kL / nodes) {
        EXPECT_NEAR(d.theta[k], kH1 / kH2, 1e-9) << "x = " << d.x[k];
        EXPECT_LE(std::abs(d.p[k]), 1e-9 * exact.peak);
      }
      if (d.x[k] < kA - kL / nodes) {
        EXPECT_NEAR(d.theta[k], 1.0, 1e-9);
      }
    }
    EXPECT_LT(error, exact.front_slope * dx * dx) << nodes << " nodes per pad";
    std::printf("[ jfo step slider ] %d nodes per pad: front %.5g mm (exact %.5g), load %.7g N/m (exact %.7g)\n",
                nodes, front * 1e3, exact.front * 1e3, d.load, exact.load);
  }
}

}  // namespace
}  // namespace twb
