// The fields of a solved state (film_fields.h) agree with the state's reported
// quantities wherever analysis ties them together:
//   a. the trapezoid rule over the written pressure reproduces the reported fluid force
//      to rounding (see below why it is exact, not only to discretization order);
//   b. the smallest nodal gap of the sliding film lies within the rim's sagitta of the
//      plane's exact minimum h_min (docs/physics.md section 9);
//   c. contact pressure is non-negative, non-increasing in the gap (one law for both
//      films) and present at the tight rim of each film; on film 2, which carries the
//      load by contact alone, the trapezoid rule over it converges to the load at
//      second order;
//   d. temperatures: the hottest film node is the state's T_max, nothing is colder than
//      ambient (heat is only generated, and lost only to ambient), and the viscosity is
//      Roelands' at the surfaces' mean temperature (the paper's rule, the default);
//   e. without hydrodynamics or heat, pressure is 0 and every temperature the ambient.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "physics/roelands_viscosity.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

struct Solved {
  std::vector<double> u;
  BearingState state;
  std::vector<FilmFields> fields;
};

Solved solve(BearingModel& m) {
  SteadySolver solver(m, {});
  Solved s;
  const SteadyReport rep = solver.solve_cold(s.u);
  EXPECT_TRUE(rep.converged) << rep.message;
  s.state = m.describe(s.u);
  s.fields = m.fields(s.u);
  return s;
}

// ∫ v r dr dθ over the annulus by the trapezoid rule on the nodes (periodic in θ).
double trapezoid(const FilmMesh& m, const std::vector<double>& v) {
  double sum = 0.0;
  for (int i = 0; i < m.radial_nodes(); ++i) {
    const double w = (i == 0 || i == m.radial_nodes() - 1) ? 0.5 * m.dr() : m.dr();
    for (int j = 0; j < m.circumferential_nodes(); ++j) sum += v[std::size_t(m.node(i, j))] * m.radius(i) * w * m.dtheta();
  }
  return sum;
}

// The paper's case at 545 rad/s and 150 N: mostly hydrodynamic, some contact at the rim.
class PaperCaseFields : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new BearingModel(testing::table1_scene(true, true, true, true, 545.0, 150.0));
    solved_ = new Solved(solve(*model_));
  }
  static void TearDownTestSuite() {
    delete solved_;
    delete model_;
  }
  static BearingModel* model_;
  static Solved* solved_;
};
BearingModel* PaperCaseFields::model_ = nullptr;
Solved* PaperCaseFields::solved_ = nullptr;

TEST_F(PaperCaseFields, OneSetPerFilmOnItsGrid) {
  const auto& f = solved_->fields;
  ASSERT_EQ(f.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(f[k].film, int(k) + 1);
    EXPECT_EQ(f[k].sliding, model_->films()[k].sliding);
    EXPECT_EQ(f[k].mesh.inner_radius(), model_->films()[k].mesh.inner_radius());
    const std::size_t n = std::size_t(f[k].mesh.node_count());
    for (const auto* v : {&f[k].gap, &f[k].pressure, &f[k].contact_pressure, &f[k].film_temperature,
                          &f[k].surface_temperature, &f[k].viscosity})
      EXPECT_EQ(v->size(), n);
  }
  EXPECT_TRUE(f[0].sliding);
  EXPECT_FALSE(f[1].sliding);
}

// The model integrates the bilinear interpolant of the nodal pressures times r over each
// cell with a 4×4 Gauss rule, which is exact for it (degree 2 in r, 1 in θ). That
// integral is Σ p_ij ∫hat_i r dr Δθ, and for an interior node ∫hat_i r dr = r_i Δr,
// the trapezoid weight; edge nodes carry p = 0. So the trapezoid rule on the written
// field equals the reported force up to summation rounding (~1e-15 per term).
TEST_F(PaperCaseFields, TrapezoidPressureIntegralIsTheFluidForce) {
  const FilmFields& f = solved_->fields[0];
  const double force = trapezoid(f.mesh, f.pressure);
  ASSERT_GT(solved_->state.fluid_force, 0.1 * solved_->state.load) << "the case must be carried by the film";
  EXPECT_NEAR(force, solved_->state.fluid_force, 1e-12 * solved_->state.fluid_force);
  // The Reynolds condition: no pressure below ambient, beyond the solver's tolerance
  // (1e-10 on p̂ = p / p_ref).
  for (double p : f.pressure) EXPECT_GE(p, -1e-9 * model_->pressure_scale());
  // The film that does not slide has no pressure unknowns.
  for (double p : solved_->fields[1].pressure) EXPECT_EQ(p, 0.0);
}

// The plane's minimum over the annulus lies on the outer rim, at the angle θ* opposite
// its gradient; the nearest rim node is at most Δθ/2 away, where the plane is higher by
// |∇h| r_o (1 − cos(Δθ/2)) (|∇h| r_o = c − h_min). Nodes never undercut the exact minimum.
TEST_F(PaperCaseFields, SmallestNodalGapIsTheExactMinimumUpToTheSagitta) {
  const FilmFields& f = solved_->fields[0];
  const double sigma = model_->films()[0].sigma;
  const double hmin = solved_->state.hmin_over_sigma * sigma;
  const double c = solved_->state.position.c1;
  const double sagitta = (c - hmin) * (1.0 - std::cos(0.5 * f.mesh.dtheta()));
  const double smallest = *std::min_element(f.gap.begin(), f.gap.end());
  const double rounding = 1e-12 * c;
  EXPECT_GE(smallest, hmin - rounding);
  EXPECT_LE(smallest, hmin + sagitta + rounding);
  // And the smallest gap is on the outer rim.
  const auto at = std::size_t(std::min_element(f.gap.begin(), f.gap.end()) - f.gap.begin());
  EXPECT_EQ(int(at) / f.mesh.circumferential_nodes(), f.mesh.radial_nodes() - 1);
}

TEST_F(PaperCaseFields, ContactIsNonNegativeFallsWithTheGapAndSitsAtTheTightRim) {
  struct Node { double h, p; };
  std::vector<Node> nodes;
  for (const FilmFields& f : solved_->fields) {
    for (std::size_t k = 0; k < f.gap.size(); ++k) {
      EXPECT_GE(f.contact_pressure[k], 0.0);
      nodes.push_back({f.gap[k], f.contact_pressure[k]});
    }
    const auto tight = std::size_t(std::min_element(f.gap.begin(), f.gap.end()) - f.gap.begin());
    EXPECT_EQ(f.contact_pressure[tight], *std::max_element(f.contact_pressure.begin(), f.contact_pressure.end()));
    EXPECT_GT(f.contact_pressure[tight], 0.0) << "film " << f.film;
  }
  std::sort(nodes.begin(), nodes.end(), [](const Node& a, const Node& b) { return a.h < b.h; });
  for (std::size_t k = 1; k < nodes.size(); ++k) EXPECT_LE(nodes[k].p, nodes[k - 1].p) << "gap " << nodes[k].h;
  // Film 2 carries the whole load by contact alone (it has no fluid): its peak nodal
  // contact pressure must be at least the load over its area.
  const FilmFields& f2 = solved_->fields[1];
  EXPECT_GT(*std::max_element(f2.contact_pressure.begin(), f2.contact_pressure.end()),
            solved_->state.load / f2.mesh.area());
}

// Film 2 has no fluid, so by the washer's and the gear's balances its contact carries
// exactly the load. Its nodal contact pressure is smooth on the grid's scale (the film
// is nearly parallel: h/σ varies by about 2 over the annulus), so the trapezoid rule
// over it converges to the load at second order: 8 → 16 radial cells divides the radial
// part of the error by 4, 66 → 130 angles the angular part by (130/66)² ≈ 3.9, so the
// error falls by 3.9 to 4 (3.9 observed). [3.5, 4.5] admits that and rejects first
// order (2) or no convergence (1).
double film2_contact_error(const std::vector<FilmFields>& fields, double load) {
  return std::abs(trapezoid(fields[1].mesh, fields[1].contact_pressure) - load) / load;
}

TEST_F(PaperCaseFields, NodalContactOfTheSecondFilmIntegratesToTheLoadAtSecondOrder) {
  const double coarse = film2_contact_error(solved_->fields, solved_->state.load);
  Scene fine_scene = model_->scene();
  fine_scene.mesh.radial_nodes = 17;
  fine_scene.mesh.circumferential_nodes = 130;
  BearingModel fine_model(fine_scene);
  const Solved fine = solve(fine_model);
  const double refined = film2_contact_error(fine.fields, fine.state.load);
  EXPECT_LT(coarse, 0.01);
  EXPECT_GT(coarse / refined, 3.5) << coarse << " then " << refined;
  EXPECT_LT(coarse / refined, 4.5) << coarse << " then " << refined;
}

TEST_F(PaperCaseFields, TemperaturesMatchTheStateAndSetTheViscosity) {
  const double ambient = model_->scene().operating.ambient;
  const Lubricant& lub = model_->scene().lubricant;
  const RoelandsViscosity roelands{lub.mu_infinity, lub.g0, lub.s0};
  double hottest = ambient;
  for (const FilmFields& f : solved_->fields) {
    for (std::size_t k = 0; k < f.gap.size(); ++k) {
      hottest = std::max(hottest, f.film_temperature[k]);
      // Heat rows are solved to 1e-10 K.
      EXPECT_GE(f.film_temperature[k], ambient - 1e-8);
      EXPECT_GE(f.surface_temperature[k], ambient - 1e-8);
      const double mu = roelands(f.surface_temperature[k]).value;
      EXPECT_NEAR(f.viscosity[k], mu, 1e-13 * mu);
    }
  }
  EXPECT_EQ(hottest, solved_->state.max_film_temperature);
  EXPECT_GT(hottest, ambient + 1.0) << "the sliding film heats up";
}

// Contact only, isothermal, at rest: no pressure unknowns and no heat.
TEST(FilmFields, WithoutHydrodynamicsOrHeatPressureIsZeroAndTemperatureAmbient) {
  BearingModel m(testing::table1_scene(false, false, true, false, 0.0, 300.0));
  const Solved s = solve(m);
  const double ambient = m.scene().operating.ambient;
  ASSERT_EQ(s.fields.size(), 2u);
  for (const FilmFields& f : s.fields) {
    for (std::size_t k = 0; k < f.gap.size(); ++k) {
      EXPECT_EQ(f.pressure[k], 0.0);
      EXPECT_EQ(f.film_temperature[k], ambient);
      EXPECT_EQ(f.surface_temperature[k], ambient);
      EXPECT_EQ(f.viscosity[k], s.fields[0].viscosity[0]);
    }
    EXPECT_GT(*std::max_element(f.contact_pressure.begin(), f.contact_pressure.end()), 0.0);
  }
}

}  // namespace
}  // namespace twb
