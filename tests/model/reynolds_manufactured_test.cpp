// Order of accuracy of the Reynolds finite volumes (docs/physics.md section 3) by the method of
// manufactured solutions, on the paper's washer annulus (5.55 … 11.35 mm).
//
// Film: a tilted plane like the bearing's, h = c + a·x + b·y > 0 everywhere, constant μ,
// no flow factors (g = h³/(12μ), carried gap h). Manufactured pressure
//   p*(r, θ) = P0 · sin(π (r − r_i)/(r_o − r_i)) · (1.5 + cos(θ − θ0)),
// zero on both radii, periodic, positive inside, so the cavitation condition is inactive
// and the discrete problem is the linear system w(p) = S.
//
// The source. The scheme's w is the net outflow of a control volume, the discrete form
// of ∮ q·n ds with q = −g∇p + (ωr/2) h e_θ. So S is the same integral for p*: the exact
// flux of p* integrated (Gauss–Legendre, 8 points, error far below the scheme's) over
// the four sides of every control volume, not the point value div q(p*)·area. Then
// w(p*) − S is exactly the scheme's flux truncation error (midpoint rule on each face,
// central difference across it), summed conservatively over the faces, and p − p*
// measures the discretization alone; a point source would add the area quadrature's
// own error and would not notice a control volume that differs from the one the
// fluxes bound.
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "model/gauss_rule.h"
#include "twb/model/film_mesh.h"
#include "model/reynolds_operator.h"

namespace twb {
namespace {

constexpr double kPi = std::numbers::pi;

struct Manufactured {
  double ri = 5.55e-3, ro = 11.35e-3;
  double c = 20e-6, a = -1.0e-3, b = 0.4e-3;  // h ≥ 20 − 12.2 = 7.8 µm at r_o
  double mu = 0.02, omega = 200.0;            // Pa s, rad/s
  double p0 = 2e6, theta0 = 0.7;              // Pa, rad

  double h(double r, double th) const { return c + a * r * std::cos(th) + b * r * std::sin(th); }
  double g(double r, double th) const { return std::pow(h(r, th), 3) / (12.0 * mu); }
  double s(double r) const { return (r - ri) / (ro - ri); }
  double p(double r, double th) const { return p0 * std::sin(kPi * s(r)) * (1.5 + std::cos(th - theta0)); }
  double dp_dr(double r, double th) const {
    return p0 * kPi / (ro - ri) * std::cos(kPi * s(r)) * (1.5 + std::cos(th - theta0));
  }
  double dp_dth(double r, double th) const { return -p0 * std::sin(kPi * s(r)) * std::sin(th - theta0); }
  // Exact flux components: q_r = −g ∂p/∂r, q_θ = −g (1/r) ∂p/∂θ + (ω r/2) h.
  double q_r(double r, double th) const { return -g(r, th) * dp_dr(r, th); }
  double q_th(double r, double th) const { return -g(r, th) * dp_dth(r, th) / r + 0.5 * omega * r * h(r, th); }

  // ∮ q·n ds over a control volume: outward flux through its four sides.
  double boundary_flux(const ReynoldsOperator::ControlVolume& cv, const GaussRule& rule) const {
    double out = 0.0;
    for (std::size_t k = 0; k < rule.points.size(); ++k) {
      const double th = cv.theta_lo + rule.points[k] * (cv.theta_hi - cv.theta_lo);
      const double dth = rule.weights[k] * (cv.theta_hi - cv.theta_lo);
      out += (q_r(cv.r_hi, th) * cv.r_hi - q_r(cv.r_lo, th) * cv.r_lo) * dth;
      const double r = cv.r_lo + rule.points[k] * (cv.r_hi - cv.r_lo);
      const double dr = rule.weights[k] * (cv.r_hi - cv.r_lo);
      out += (q_th(r, cv.theta_hi) - q_th(r, cv.theta_lo)) * dr;
    }
    return out;
  }
};

struct Errors {
  double max_norm, l2;  // relative to max |p*| and to the L2 norm of p*
  double residual;      // max |w(p) − S| / max |S| after the solve
};

Errors solve_on(const Manufactured& mf, int nr, int nt) {
  const FilmMesh mesh(mf.ri, mf.ro, nr, nt);
  const ReynoldsOperator op(mesh);
  const int n = op.interior_count();

  // Face quantities at the face midpoints, as the operator prescribes.
  const auto faces = std::size_t(op.face_count());
  std::vector<double> g(faces), carried(faces);
  op.for_each_face([&](const ReynoldsFace& f) {
    g[f.index] = mf.g(f.r, f.theta);
    carried[f.index] = mf.h(f.r, f.theta);
  });

  // w is affine in p: w(p) = A p + w(0).
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& e : op.pressure_coefficients(g)) entries.emplace_back(e.row, e.col, e.value);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());

  const GaussRule rule = GaussRule::legendre(8);
  const auto size = std::size_t(n);
  std::vector<double> zero(size, 0.0), exact(size), source(size), cv_area(size);
  for (int i = 1; i < nr - 1; ++i) {
    for (int j = 0; j < nt; ++j) {
      const int k = op.interior_index(i, j);
      const auto cv = op.control_volume(i, j);
      exact[k] = mf.p(mesh.radius(i), mesh.angle(j));
      source[k] = mf.boundary_flux(cv, rule);
      cv_area[k] = mesh.radius(i) * mesh.dr() * mesh.dtheta();
    }
  }
  const std::vector<double> w0 = op.net_outflow(mf.omega, g, carried, zero);
  Eigen::VectorXd rhs(n);
  for (int k = 0; k < n; ++k) rhs[k] = source[k] - w0[k];

  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(A);
  EXPECT_EQ(lu.info(), Eigen::Success);
  const Eigen::VectorXd sol = lu.solve(rhs);
  const std::vector<double> p(sol.data(), sol.data() + n);

  // The solve must satisfy the operator's own balance, not only the matrix built here.
  const std::vector<double> w = op.net_outflow(mf.omega, g, carried, p);
  double res = 0.0, s_max = 0.0, e_max = 0.0, p_max = 0.0, e2 = 0.0, p2 = 0.0;
  for (int k = 0; k < n; ++k) {
    res = std::max(res, std::abs(w[k] - source[k]));
    s_max = std::max(s_max, std::abs(source[k]));
    e_max = std::max(e_max, std::abs(p[k] - exact[k]));
    p_max = std::max(p_max, std::abs(exact[k]));
    e2 += cv_area[k] * (p[k] - exact[k]) * (p[k] - exact[k]);
    p2 += cv_area[k] * exact[k] * exact[k];
  }
  return {e_max / p_max, std::sqrt(e2 / p2), res / s_max};
}

TEST(ReynoldsManufactured, SecondOrderOnTheWasherAnnulus) {
  const Manufactured mf;
  const std::vector<std::pair<int, int>> meshes{{9, 66}, {17, 132}, {33, 264}, {65, 528}};
  std::vector<Errors> err;
  std::printf("  mesh (Nr, Ntheta)   max error   order   L2 error   order   |w(p)-S|/|S|\n");
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    err.push_back(solve_on(mf, meshes[m].first, meshes[m].second));
    const Errors& e = err.back();
    if (m == 0) {
      std::printf("  (%3d, %3d)          %.3e      -     %.3e      -     %.1e\n", meshes[m].first,
                  meshes[m].second, e.max_norm, e.l2, e.residual);
      continue;
    }
    const double order_max = std::log2(err[m - 1].max_norm / e.max_norm);
    const double order_l2 = std::log2(err[m - 1].l2 / e.l2);
    std::printf("  (%3d, %3d)          %.3e   %5.3f   %.3e   %5.3f   %.1e\n", meshes[m].first, meshes[m].second,
                e.max_norm, order_max, e.l2, order_l2, e.residual);
    EXPECT_GE(order_max, 1.8) << "max-norm order between meshes " << m - 1 << " and " << m;
    EXPECT_LE(order_max, 2.2) << "max-norm order between meshes " << m - 1 << " and " << m;
    EXPECT_GE(order_l2, 1.8) << "L2 order between meshes " << m - 1 << " and " << m;
    EXPECT_LE(order_l2, 2.2) << "L2 order between meshes " << m - 1 << " and " << m;
  }
  for (const Errors& e : err) EXPECT_LT(e.residual, 1e-9);  // the linear solve is exact to rounding
  EXPECT_LT(err.back().max_norm, 1e-3);
}

}  // namespace
}  // namespace twb
