// The oil's heat carried by its flow as an operator, against a manufactured film
// temperature (docs/physics.md section 15): the scheme's truncation error at its order.
//
// On a parallel film at rest pressure (no tilt, every pressure 0: the Couette flow alone,
// Q = the same flux through every circumferential face of a radial row, none through the
// radial faces), put T(θ) = ΔT (sin θ + ½ cos 2θ) into the state's film temperatures. The
// heat the convection effect takes from an interior node's balance is the upwind
// difference ρc Q (T_j − T_{j−1}) (the node's row with convection less the same row
// without); the advection over the node's control volume is ρc Q Δθ T'(θ_j). By Taylor,
//
//     ρc Q (T_j − T_{j−1}) − ρc Q Δθ T'(θ_j) = −ρc Q Δθ² T''(θ_j)/2 + ρc Q Δθ³ T'''(ξ)/6,
//
// first order relative to the advection. The test requires that difference's leading term
// to within the remainder's bound ρc |Q| Δθ³ max|T'''|/6 at every node, and the observed
// order of the largest error over Δθ, Δθ/2, Δθ/4 to be 1 to within 0.05.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "model/film_face_flows.h"

namespace twb {
namespace {

constexpr double kRise = 20.0;  // ΔT, K
double temperature(double t) { return kRise * (std::sin(t) + 0.5 * std::cos(2 * t)); }
double slope(double t) { return kRise * (std::cos(t) - std::sin(2 * t)); }
double curvature(double t) { return kRise * (-std::sin(t) - 2 * std::cos(2 * t)); }
constexpr double kMostThirdDerivative = kRise * (1.0 + 4.0);  // |−cos θ + 4 sin 2θ| ≤ 5 ΔT

struct OrderResult {
  double largest_error = 0.0;   // max over interior nodes of |upwind − advection|
  double largest_advection = 0.0;
  int beyond_remainder = 0;     // nodes whose error is not the leading term within the remainder
};

OrderResult upwind_against_advection(int circumferential_nodes) {
  Scene with = testing::wide_parallel_annulus(545.0, 100.0);
  with.effects.thermal = true;
  with.effects.convection = true;
  with.mesh.radial_nodes = 5;
  with.mesh.circumferential_nodes = circumferential_nodes;
  Scene without = with;
  without.effects.convection = false;
  const BearingModel on(with), off(without);
  if (on.layout().size() != off.layout().size()) throw std::logic_error("convection added unknowns");

  const Film& film = on.sliding_film();
  const FilmMesh& m = film.mesh;
  std::vector<double> u = on.cold_start();
  for (int i = 0; i < m.radial_nodes(); ++i)
    for (int j = 0; j < m.circumferential_nodes(); ++j)
      u[std::size_t(film.temperature_offset + m.node(i, j))] = temperature(m.angle(j));
  std::vector<double> r_on(u.size()), r_off(u.size());
  on.evaluate(u, r_on, {});
  off.evaluate(u, r_off, {});

  // Each radial row's flux through its circumferential faces, towards +θ.
  std::vector<double> flux(std::size_t(m.radial_nodes()), 0.0);
  FilmFaceFlows(on, film, u).for_each([&](const FaceFlow& f) {
    if (!f.circumferential) return;
    const bool forward = m.wrap(f.face.ja + 1) == f.face.jb;
    flux[std::size_t(f.face.ia)] = forward ? f.flux.q : -f.flux.q;
  });
  const double rho_c = with.lubricant.density_at(with.operating.ambient) * with.lubricant.specific_heat;
  const double dt = m.dtheta();

  OrderResult out;
  // The rows read heat out − heat in (orient_rows): the heat the oil takes is +.
  for (int i = 1; i < m.radial_nodes() - 1; ++i) {
    const double q = flux[std::size_t(i)];
    EXPECT_GT(q, 0.0) << "the Couette flow runs towards +theta in row " << i;
    for (int j = 0; j < m.circumferential_nodes(); ++j) {
      const Index row = film.temperature_offset + m.node(i, j);
      const double carried = (r_on[std::size_t(row)] - r_off[std::size_t(row)]) / on.layout().row_scale(row);
      const double t = m.angle(j);
      const double advection = rho_c * q * dt * slope(t);
      const double error = carried - advection;
      const double leading = -rho_c * q * dt * dt * curvature(t) / 2;
      const double remainder = rho_c * std::abs(q) * dt * dt * dt * kMostThirdDerivative / 6;
      if (!(std::abs(error - leading) <= 1.001 * remainder + 1e-12 * std::abs(advection))) ++out.beyond_remainder;
      out.largest_error = std::max(out.largest_error, std::abs(error));
      out.largest_advection = std::max(out.largest_advection, std::abs(advection));
    }
  }
  return out;
}

TEST(ConvectionOrder, TheUpwindSchemeIsFirstOrderAgainstAManufacturedTemperature) {
  std::vector<double> relative;
  for (const int nt : {36, 72, 144}) {
    const OrderResult r = upwind_against_advection(nt);
    EXPECT_EQ(r.beyond_remainder, 0) << nt << " nodes round";
    ASSERT_GT(r.largest_advection, 0.0);
    relative.push_back(r.largest_error / r.largest_advection);
  }
  for (std::size_t k = 1; k < relative.size(); ++k) {
    const double order = std::log2(relative[k - 1] / relative[k]);
    EXPECT_NEAR(order, 1.0, 0.05) << "refinement " << k;
  }
}

}  // namespace
}  // namespace twb
