// The washer as an elastic plate (docs/physics.md section 21) in the bearing: what it
// costs in unknowns, a converged state's balances (the films' and the plate's own), the
// stiff washer's limit, and its thermal curvature. The plate operator's closed forms are
// tests/physics/elastic_annulus_test.cpp; its Jacobian is jacobian_test.cpp's; with the
// effect off every other test is unchanged.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "../support/converged_balances.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "model/elastic_washer_effect.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

struct Solved {
  std::unique_ptr<BearingModel> model;
  std::vector<double> u;
  BearingState state;
};

Solved solve(const Scene& s) {
  Solved out{std::make_unique<BearingModel>(s), {}, {}};
  SteadySolver solver(*out.model, {});
  const SteadyReport rep = solver.solve_cold(out.u);
  EXPECT_TRUE(rep.converged) << rep.message;
  out.state = out.model->describe(out.u);
  return out;
}

Scene coarse_scene(double load) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, load);
  testing::use_coarse_mesh(s);
  return s;
}

const ElasticWasherEffect& plate_of(const BearingModel& m) {
  const auto* plate = m.effect<ElasticWasherEffect>();
  if (!plate) throw std::logic_error("no elastic washer");
  return *plate;
}

TEST(ElasticWasherModel, AddsTwoUnknownsPerWasherNodeAndThreeMultipliers) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  const BearingModel plain(s);
  s.effects.elastic_washer = true;
  const BearingModel elastic(s);
  const int nodes = s.mesh.radial_nodes * s.mesh.circumferential_nodes;
  // w and m per node, the three multipliers and, the gap now having a part, the contact
  // force's own unknown (the empirical friction law).
  EXPECT_EQ(elastic.size(), plain.size() + 2 * nodes + 3 + 1);
  EXPECT_TRUE(elastic.pattern().prefers_nested_dissection);
  EXPECT_FALSE(plain.pattern().prefers_nested_dissection);
}

// A solver that fails names the row it failed on: each of the plate's rows says which of
// its balances it is, and where (row_meaning.cpp), not the block's bare name.
TEST(ElasticWasherModel, ThePlatesRowsSayWhatTheyBalanceAndWhere) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  s.effects.elastic_washer = true;
  const BearingModel model(s);
  const int nodes = s.mesh.radial_nodes * s.mesh.circumferential_nodes;
  int curvature = 0, load = 0, rigid = 0;
  for (Index k = 0; k < model.size(); ++k) {
    const std::string row = model.describe_row(k);
    curvature += row.find("the washer plate's curvature") == 0 && row.find(" at node (") != std::string::npos;
    load += row.find("the washer plate's load balance") == 0 && row.find(" at node (") != std::string::npos;
    rigid += row.find("the washer plate's rigid plane (the integral of w") == 0;
  }
  EXPECT_EQ(curvature, nodes);
  EXPECT_EQ(load, nodes);
  EXPECT_EQ(rigid, 3);
}

// The films carry the load and the washer's three rigid rows balance it (to 1e-8 of the
// load: converged_balances.h); the plate's own balance is its multipliers: the nodes'
// loads sum to the washer's net force, zero, so λ0 is the solver's tolerance (its rows
// are solved to 1e-10 of F_ref each, over the washer's area), and λ1, λ2 take up the
// difference between the films' moment integrals and the nodes' moment sums, of the
// discretization's order: below 1 % of the films' moments over the washer's second moment.
TEST(ElasticWasherModel, ConvergedStateMeetsTheFilmsAndThePlatesBalances) {
  for (const bool thermal_curvature : {false, true}) {
    SCOPED_TRACE(thermal_curvature ? "with thermal deformation" : "without");
    Scene s = coarse_scene(150.0);
    s.effects.elastic_washer = true;
    s.effects.thermal_deformation = thermal_curvature;
    const Solved c = solve(s);
    testing::expect_balanced(c.state);
    const ElasticWasherEffect& plate = plate_of(*c.model);
    const std::array<double, 3> lambda = plate.multipliers(c.u);
    const double ri = s.washer.inner_radius, ro = s.washer.outer_radius;
    const double area = std::numbers::pi * (ro * ro - ri * ri);
    const double second_moment = std::numbers::pi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4.0;
    EXPECT_LT(std::abs(lambda[0]) * area, 1e-8 * s.operating.load);
    for (const double l : {lambda[1], lambda[2]}) EXPECT_LT(std::abs(l) * second_moment, 1e-2 * s.operating.load * ro);
    // It bends: beyond its rigid plane by more than a tenth of the least film.
    const std::vector<double> w = plate.deflection(c.u);
    const auto [least, most] = std::minmax_element(w.begin(), w.end());
    EXPECT_GT(*most - *least, 0.1 * c.state.hmin_over_sigma * c.model->clearance_scale());
  }
}

// As the washer's modulus grows its state tends to the rigid washer's as 1/E: the
// differences at 10⁵ and 10⁶ times steel's stand in the ratio 10 to the next order's
// share, which falls as 1/E too (the contact law bends the response: at 10², 10³, 10⁴
// times steel's the successive ratios were 6.1, 7.7, 9.7, so the share is 3 % at 10⁴ and
// 0.3 % at 10⁵; 1 % asked). Each against the rigid washer of its own modulus: the
// modulus is also the asperities' (their composite modulus, docs/physics.md section 4).
TEST(ElasticWasherModel, AStiffWasherTendsToTheRigidOneAsOneOverItsModulus) {
  auto difference = [&](double stiffer) {
    Scene s = coarse_scene(150.0);
    s.washer.material.youngs_modulus *= stiffer;
    const Solved rigid = solve(s);
    s.effects.elastic_washer = true;
    const Solved c = solve(s);
    // The rigid body (its first four unknowns in both layouts) and the least film.
    double d = 0.0;
    for (int k = 0; k < 4; ++k) d = std::max(d, std::abs(c.u[std::size_t(k)] - rigid.u[std::size_t(k)]));
    return std::max(d, std::abs(c.state.hmin_over_sigma - rigid.state.hmin_over_sigma));
  };
  const double at_1e5 = difference(1e5), at_1e6 = difference(1e6);
  EXPECT_GT(at_1e6, 1e-7);  // far beyond the solver's tolerance: the test measures something
  EXPECT_NEAR(at_1e5 / at_1e6, 10.0, 0.1);
}

// With thermal deformation the heat crossing the washer curves it where it crosses: the
// w rows' thermal part, Σ_a A_a·(1 + ν)·κ_T,a = (1 + ν)·α/K·(the heat crossing the
// mid-plane), is (1 + ν) times §11's mean curvature κ̄ times the washer's area, κ̄ being
// what the dishing row makes of the same flows. Read off the plate's own rows at the
// solved state (their operator applied to w and m: the balance of each w row is its
// thermal part), to the rows' tolerance (1e-10 of σ_ref each: 1e-6 asked).
TEST(ElasticWasherModel, TheHeatCrossingTheWasherIsItsThermalCurvature) {
  Scene s = coarse_scene(150.0);
  s.effects.elastic_washer = true;
  s.effects.thermal_deformation = true;
  const Solved c = solve(s);
  const ElasticWasherEffect& plate = plate_of(*c.model);
  const ElasticAnnulus& a = plate.annulus();
  const std::vector<double> w = plate.deflection(c.u), m = plate.curvature_sum(c.u);
  const std::array<double, 3> lambda = plate.multipliers(c.u);
  const int n = a.nodes();
  auto value = [&](int k) { return k < n ? w[std::size_t(k)] : k < 2 * n ? m[std::size_t(k - n)] : lambda[std::size_t(k - 2 * n)]; };
  double thermal = 0.0;
  for (const ElasticAnnulus::Entry& e : a.entries())
    if (e.row < n) thermal += e.value * value(e.column);
  const double ri = s.washer.inner_radius, ro = s.washer.outer_radius;
  const double expected = (1.0 + s.washer.material.poisson_ratio) * c.model->dishing_curvature(c.u) * std::numbers::pi *
                          (ro * ro - ri * ri);
  EXPECT_GT(c.model->dishing_curvature(c.u), 0.0);  // heat flows from the sliding film 1 into the washer
  EXPECT_NEAR(thermal, expected, 1e-6 * std::abs(expected));
}

// A washer whose modulus follows its data over temperature (physics §23) bends, at a
// uniform temperature, as the washer of the constant modulus E(T) there: the same state to
// the solver's tolerance (its rows to 1e-10 of their scales; 1e-6 of the bending asked).
// Without the thermal effect the washer is at the ambient everywhere. The curve's
// reference modulus (youngs_modulus) is half E(T), so the rigidity's factor is 2, not 1;
// the asperities still take the reference modulus (§23: their E'(T) is planned), so the
// constant washer's counterfaces are softened until both films' composite modulus (§4)
// is the curved washer's. (Without contact this coarse washer does not converge.)
TEST(ElasticWasherModel, AtAUniformTemperatureTheCurvesWasherIsTheConstantOnes) {
  Scene curved = coarse_scene(150.0);
  curved.effects.thermal = false;
  curved.effects.elastic_washer = true;
  const double t0 = curved.operating.ambient;
  // Linear in ln E between the two points: E(t0) = (400 GPa · 100 GPa)^½ = 200 GPa.
  curved.washer.material.modulus_by_temperature = {{t0 - 50.0, 400e9}, {t0 + 50.0, 100e9}};
  curved.washer.material.youngs_modulus = 100e9;
  Scene constant = curved;
  constant.washer.material.modulus_by_temperature.clear();
  constant.washer.material.youngs_modulus = 200e9;
  const double nu_w = curved.washer.material.poisson_ratio;
  for (Component* c : {&constant.carrier, &constant.gear}) {
    const double nu = c->material.poisson_ratio;
    c->material.youngs_modulus =
        (1.0 - nu * nu) / ((1.0 - nu * nu) / c->material.youngs_modulus + (1.0 - nu_w * nu_w) * (1.0 / 100e9 - 1.0 / 200e9));
  }
  const Solved a = solve(curved), b = solve(constant);
  const std::vector<double> wa = plate_of(*a.model).deflection(a.u), wb = plate_of(*b.model).deflection(b.u);
  const auto [least, most] = std::minmax_element(wb.begin(), wb.end());
  const double bending = *most - *least;
  EXPECT_GT(bending, 0.0);
  for (std::size_t k = 0; k < wa.size(); ++k) EXPECT_NEAR(wa[k], wb[k], 1e-6 * bending);
  // and unlike the washer of its reference modulus (the curve ignored), which bends more.
  Scene reference = curved;
  reference.washer.material.modulus_by_temperature.clear();
  const Solved c = solve(reference);
  const std::vector<double> wc = plate_of(*c.model).deflection(c.u);
  const auto [least_c, most_c] = std::minmax_element(wc.begin(), wc.end());
  EXPECT_GT(*most_c - *least_c, 1.2 * bending);
}

}  // namespace
}  // namespace twb
