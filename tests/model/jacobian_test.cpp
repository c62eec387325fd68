// The assembled Jacobian against central finite differences of the residual, at
// random states, for every combination of effects (issue: exact sparse Jacobian).
//
// Richardson-extrapolated central differences, (4 D(ε/2) − D(ε))/3, have truncation
// error O(ε⁴) where the residual is smooth, but rounding error O(u·T/ε), with
// u = 2.2e-16 and T the size of the terms a row sums (a flow balance sums face fluxes
// up to ~1e4 times its scale). No single ε suits every column, so each entry is
// differenced at ε = 1e-2 … 1e-6 (scaled unknowns). The uncertainty of each estimate
// is its distance to the next smaller step's (truncation) plus the rounding bound
// 1e2·u·T/ε with T = |r_i| + Σ_j |J_ij·u_j| (the size of the row's terms; 1e2 covers
// accumulation over a row's sums), and the estimate with the smallest uncertainty is
// kept. An entry is above noise when that uncertainty is below 1e-7 of it; such entries
// must agree to 1e-6 relative, and nearly all entries must be above noise so the check
// is not vacuous. Entries the pattern does not hold must vanish under differencing
// (the pattern is complete).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <numbers>
#include <random>

#include "../support/prescribed_wear.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "solver/consistent_rates.h"
#include "solver/natural_continuation.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

struct EffectSet {
  const char* name;
  bool hydro, factors, contact, thermal;
  double speed;
  CarrierTemperature carrier = CarrierTemperature::load_frame;
  CavitationRow cavitation = CavitationRow::fischer_burmeister;
  bool deformation = false;
  FrictionLaw friction = FrictionLaw::empirical;
  CavitationModel cavitation_model = CavitationModel::reynolds;
  int grooved_film = 0;  // 1 or 2: three tapered-land grooves on that washer face (film 2 slides)
  bool fed = false;      // oil supplied at the bore and into the grooves
  bool convection = false;
  bool dammed = false;   // the grooves closed at radial line 2 of 5, open at the bore
  bool worn = false;     // a part of film 1's gap from outside the model (support/prescribed_wear.h)
  bool wear = false;     // the sliding film's faces worn (docs/physics.md section 20)
  bool running_in = false;  // and their roughness run in, to 0.3 of its Rq new
  bool elastic = false;     // the washer bends as a plate (docs/physics.md section 21)
  // Its modulus over temperature (section 23): a polymer's fall through its glass
  // transition placed inside the random states' temperatures (ambient + 0..80 K).
  bool polymer = false;
};

class JacobianTest : public ::testing::TestWithParam<EffectSet> {};

std::vector<double> random_state(const BearingModel& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> u = m.cold_start();
  for (const UnknownBlock& b : m.layout().blocks()) {
    for (Index k = b.offset; k < b.offset + b.size; ++k) {
      if (b.effect == BlockEffect::mechanics) u[k] += 0.6 * (unit(rng) - 0.5);
      else if (b.effect == BlockEffect::thermal) u[k] = 80.0 * unit(rng);
      // Pressures away from the Fischer–Burmeister kink at (0, 0), where the residual
      // is not differentiable. (The minimum row's kink p̂ = ŵ may fall between two
      // differenced states: the spread of the step sizes then marks that entry
      // unresolved rather than wrong.)
      else if (b.effect == BlockEffect::hydrodynamics && b.name.find("content") != std::string::npos) u[k] = 0.05 + 0.9 * unit(rng);
      else if (b.effect == BlockEffect::hydrodynamics) u[k] = 0.05 + 3.0 * unit(rng);
      // Dishing κ̂ (rim lift in σ), a worn depth (in σ) and the contact force over the
      // scene's load.
      else if (b.effect == BlockEffect::thermal_deformation) u[k] = b.name == "washer dishing curvature" ? 2.0 * unit(rng) - 1.0 : 0.2 + unit(rng);
      else if (b.effect == BlockEffect::asperity_contact) u[k] = 0.2 + unit(rng);
      else if (b.effect == BlockEffect::wear) u[k] = 0.2 + unit(rng);
      // The plate's deflection (in σ), curvature sum and multipliers, either sign.
      else if (b.effect == BlockEffect::elastic_washer) u[k] = unit(rng) - 0.5;
    }
  }
  return u;
}

// The bearing of an effect set on a 5 × 12 mesh.
std::unique_ptr<BearingModel> model_of(const EffectSet& e) {
  Scene s = testing::table1_scene(e.hydro, e.factors, e.contact, e.thermal, e.speed, 700.0);
  s.effects.carrier_temperature = e.carrier;
  s.effects.thermal_deformation = e.deformation;
  s.friction.law = e.friction;
  s.effects.cavitation = e.cavitation_model;
  s.mesh.radial_nodes = 5;
  s.mesh.circumferential_nodes = 12;
  if (e.grooved_film > 0) {
    // Pitch 4 cells: a groove of 2, a land of 2 whose first falls as a taper; the
    // relief's edges and its radial faces' two halves enter every row a gap does.
    s.operating.sliding = SlidingFilm::washer_gear;
    Grooves g;
    g.count = 3;
    g.film = e.grooved_film;
    g.cells = 2;
    g.width = 2 * 2 * std::numbers::pi / 12;
    g.depth = 3e-6;
    g.land = {LandShape::taper, 1e-6, 0.5};
    // A dam's line splits the control volumes and circumferential faces across it.
    if (e.dammed) g.closed_at = GrooveDam{GrooveOpening::inner_radius, 0.0, 0.0, 2};
    s.washer.grooves = g;
  }
  if (e.fed) s.lubricant.supply = OilSupply{2e5, SupplyInlet::both, s.operating.ambient + 15.0};
  s.effects.convection = e.convection;
  s.effects.wear = e.wear;
  s.effects.elastic_washer = e.elastic;
  if (e.polymer) {
    const double t0 = s.operating.ambient;
    s.washer.material.youngs_modulus = 3.7e9;
    s.washer.material.modulus_by_temperature = {
        {t0 - 10.0, 3.7e9}, {t0 + 30.0, 3.0e9}, {t0 + 40.0, 1.5e9}, {t0 + 50.0, 0.6e9}, {t0 + 100.0, 0.4e9}};
  }
  if (e.wear)
    for (Component* c : {&s.carrier, &s.washer, &s.gear}) c->roughness.wear_rate = 1e-16;
  if (e.running_in)
    for (Component* c : {&s.carrier, &s.washer, &s.gear}) c->roughness.run_in_rq = 0.3 * c->roughness.rq;
  std::vector<BearingModel::EffectMaker> more;
  if (e.worn)
    more.push_back(testing::PrescribedWear::maker(
        [sigma = s.asperities.summit_sigma, ro = s.washer.outer_radius](double r, double theta) {
          return 0.3 * sigma * (1.0 + std::cos(theta)) * r / ro;
        }));
  auto m = std::make_unique<BearingModel>(s, more);
  m->set_newton_form(e.cavitation == CavitationRow::minimum);
  return m;
}

// The residual at a state x near u, and (jacobian non-empty) its Jacobian in x.
using ResidualAt = std::function<void(std::span<const double> x, std::span<double> r, std::span<double> jac)>;

// Under the sanitizers (scripts/sanitizer_tests.sh, GCC's AddressSanitizer) the check is
// run for memory errors and undefined behaviour, not for the slopes (those the normal
// build checks on every column): every differenced evaluation assembles the whole model,
// so one column in fifteen walks the same code, and the differencing that made these
// tests a third of the sanitizers' time shrinks with it.
#if defined(__SANITIZE_ADDRESS__)
constexpr std::size_t kColumnStride = 15;
#else
constexpr std::size_t kColumnStride = 1;
#endif

// Every entry of the Jacobian `residual_at` gives at u against its differences (the
// method above) in every kColumnStride-th column and the rigid body's; `what` names the
// case in failures.
void expect_differences_match(const BearingModel& m, const std::vector<double>& u, const ResidualAt& residual_at,
                              const std::string& what) {
  const SparsePattern& p = m.pattern();
  const auto n = std::size_t(m.size());
  std::vector<double> r(n), rp(n), rm(n), rp2(n), rm2(n), jac(std::size_t(p.nnz()));
  residual_at(u, r, jac);
  std::vector<double> row_max(n, 0.0), term_size(n, 0.0);
  for (Index i = 0; i < p.rows; ++i) {
    term_size[i] = std::abs(r[i]);
    for (Index k = p.row_start[i]; k < p.row_start[i + 1]; ++k) {
      row_max[i] = std::max(row_max[i], std::abs(jac[k]));
      term_size[i] += std::abs(jac[k] * u[p.column[k]]);
    }
  }
  int checked = 0, resolved = 0;
  const std::vector<double> steps{1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  std::vector<std::vector<double>> fd(steps.size(), std::vector<double>(n));
  std::size_t differenced = 0;
  for (std::size_t c = 0; c < n; ++c) {
    // (The rigid body's few columns always: a bearing of contact alone has no other.)
    if (c % kColumnStride != 0 && m.layout().block_of(Index(c)).effect != BlockEffect::mechanics) continue;
    ++differenced;
    for (std::size_t e_i = 0; e_i < steps.size(); ++e_i) {
      const double eps = steps[e_i] * std::max(1.0, std::abs(u[c]));
      std::vector<double> x = u;
      auto at = [&](double delta, std::vector<double>& out) { x[c] = u[c] + delta; residual_at(x, out, {}); };
      at(eps, rp);
      at(-eps, rm);
      at(0.5 * eps, rp2);
      at(-0.5 * eps, rm2);
      for (std::size_t i = 0; i < n; ++i)
        fd[e_i][i] = (4.0 * (rp2[i] - rm2[i]) / eps - (rp[i] - rm[i]) / (2 * eps)) / 3.0;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Index k = p.find(Index(i), Index(c));
      const double an = k >= 0 ? jac[k] : 0.0;
      double best = fd[0][i], uncertainty = INFINITY;
      for (std::size_t e_i = 0; e_i + 1 < steps.size(); ++e_i) {
        const double rounding = 1e2 * 2.2e-16 * term_size[i] / (0.5 * steps[e_i] * std::max(1.0, std::abs(u[c])));
        const double spread = std::abs(fd[e_i][i] - fd[e_i + 1][i]) + rounding;
        if (spread < uncertainty) {
          uncertainty = spread;
          best = fd[e_i][i];
        }
      }
      const double floor = 1e-6 * std::max(row_max[i], 1e-300);
      if (k < 0) {
        EXPECT_LE(std::abs(best), std::max(floor, uncertainty))
            << what << ": entry (" << i << ", " << c << ") missing from the pattern, "
            << m.layout().block_of(Index(i)).name << " / " << m.layout().block_of(Index(c)).name;
        continue;
      }
      if (std::abs(an) < floor) {
        // An entry the assembly leaves (near) zero must vanish under differencing too: a
        // slope left out of a row shows here.
        EXPECT_LE(std::abs(best), std::max(floor, uncertainty))
            << what << ": entry (" << i << ", " << c << ") assembled as " << an << ", "
            << m.layout().block_of(Index(i)).name << " / " << m.layout().block_of(Index(c)).name;
        continue;
      }
      ++checked;
      if (uncertainty > 1e-7 * std::abs(an)) continue;
      ++resolved;
      EXPECT_NEAR(best, an, 1e-6 * std::abs(an))
          << what << " row " << i << " (" << m.layout().block_of(Index(i)).name << ") col " << c << " ("
          << m.layout().block_of(Index(c)).name << ")";
    }
  }
  EXPECT_GT(checked, int(differenced));
  // 75-95 % of the entries are resolved in every case; fewer would mean the check
  // had quietly become vacuous.
  EXPECT_GE(resolved, checked * 70 / 100) << what << ": too few entries resolved by differencing";
}

// The cavitation rows of Newton's form that read λ·p̂ (docs/physics.md section 3) with
// λ above 1 at u: their one entry is the diagonal, λ. (λ's own slope is left out of the
// Jacobian, which is therefore exact where λ = 1 and at the roots, where such rows have
// p̂ = 0.)
int lifted_pressure_rows(const BearingModel& m, std::span<const double> u) {
  const SparsePattern& p = m.pattern();
  std::vector<double> r(std::size_t(m.size())), jac(std::size_t(p.nnz()));
  m.evaluate(u, r, jac);
  int lifted = 0;
  for (const UnknownBlock& b : m.layout().blocks()) {
    if (b.effect != BlockEffect::hydrodynamics || b.name.find("pressure") == std::string::npos) continue;
    for (Index i = b.offset; i < b.offset + b.size; ++i) {
      double off_diagonal = 0.0, diagonal = 0.0;
      for (Index k = p.row_start[std::size_t(i)]; k < p.row_start[std::size_t(i + 1)]; ++k)
        (p.column[std::size_t(k)] == i ? diagonal : off_diagonal) += std::abs(jac[std::size_t(k)]);
      if (off_diagonal == 0.0 && diagonal > 1.0) ++lifted;
    }
  }
  return lifted;
}

TEST_P(JacobianTest, MatchesCentralDifferences) {
  const EffectSet e = GetParam();
  const std::unique_ptr<BearingModel> m = model_of(e);
  std::mt19937 rng(12345);
  for (int trial = 0; trial < 3; ++trial) {
    const std::vector<double> u = random_state(*m, rng);
    // At these states no row reads λ·p̂ with λ > 1 (where λ > 1, ŵ lies below λ·p̂), so
    // Newton's form's Jacobian is exact here; a row reading λ·p̂ is exact only at roots
    // (the test below), and a state with one would be no test of the rest.
    ASSERT_EQ(lifted_pressure_rows(*m, u), 0) << e.name << ": a random state where the Jacobian is exact only at roots";
    expect_differences_match(
        *m, u, [&](std::span<const double> x, std::span<double> r, std::span<double> jac) { m->evaluate(x, r, jac); },
        std::string(e.name) + " trial " + std::to_string(trial));
  }
}

// In the wear's slow time (docs/physics.md section 20, [W4]) the worn depths' rows are
// their rates, the friction power's slopes in every unknown of the gap: with wear on,
// the same check of every entry.
TEST(SlowTimeJacobian, MatchesCentralDifferences) {
  const EffectSet worn[] = {
      {"wear", true, true, true, true, 545.0, CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, false,
       FrictionLaw::empirical, CavitationModel::reynolds, 0, false, false, false, false, true},
      {"wear_deformation_fed_grooves_convection", true, true, true, true, 545.0, CarrierTemperature::load_frame,
       CavitationRow::fischer_burmeister, true, FrictionLaw::empirical, CavitationModel::reynolds, 2, true, true,
       false, false, true},
      {"wear_running_in", true, true, true, true, 545.0, CarrierTemperature::load_frame,
       CavitationRow::fischer_burmeister, false, FrictionLaw::empirical, CavitationModel::reynolds, 0, false, false,
       false, false, true, true}};
  std::mt19937 rng(97531);
  for (const EffectSet& e : worn) {
    auto m = model_of(e);
    m->set_time_scale(TimeScale::wear);
    for (int trial = 0; trial < 2; ++trial) {
      const std::vector<double> u = random_state(*m, rng);
      expect_differences_match(
          *m, u,
          [&](std::span<const double> x, std::span<double> r, std::span<double> jac) { m->evaluate(x, r, jac); },
          std::string(e.name) + " in slow time, trial " + std::to_string(trial));
    }
  }
}

// The gear's stop (docs/physics.md section 19): the gear's row φ(ŝ, R̂) of its distance
// from the stop and the stop's reaction, at random states around a play half a σ beyond
// the cold start's gaps (the stop engaged at some, free at others), loaded and unloaded.
TEST(GearStopJacobian, MatchesCentralDifferences) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 700.0);
  s.mesh.radial_nodes = 5;
  s.mesh.circumferential_nodes = 12;
  const BearingModel free_model(s);
  const std::vector<double> cold = free_model.cold_start();
  const Index rigid = free_model.layout().blocks().front().offset;
  s.gear.axial_play = (cold[std::size_t(rigid)] + cold[std::size_t(rigid + 3)] + 0.5) * free_model.clearance_scale();
  BearingModel m(s);
  std::mt19937 rng(2468);
  for (const double load : {700.0, 0.0}) {
    m.set_load(load);
    for (int trial = 0; trial < 2; ++trial)
      expect_differences_match(
          m, random_state(m, rng),
          [&](std::span<const double> x, std::span<double> r, std::span<double> jac) { m.evaluate(x, r, jac); },
          "the gear's stop at " + std::to_string(load) + " N, trial " + std::to_string(trial));
  }
}

// Unloaded at rest (docs/physics.md section 19) the rigid rows hold the washer and gear
// where they came to rest: u_k − held_k, and in real time a differential unknown's rate;
// at random states of a washer unloaded and standing still, held at another random state,
// steady and in time (the rates moving with the state as in IDA's iteration matrix).
TEST(RestJacobian, TheHeldRowsMatchCentralDifferences) {
  Scene s = testing::table1_scene(true, true, true, true, 0.0, 700.0);
  s.mesh.radial_nodes = 5;
  s.mesh.circumferential_nodes = 12;
  s.gear.axial_play = 1e-4;
  BearingModel m(s);
  m.set_load(0.0);
  std::mt19937 rng(1357);
  m.hold_at_rest(random_state(m, rng));
  ASSERT_TRUE(m.held_at_rest());
  expect_differences_match(
      m, random_state(m, rng),
      [&](std::span<const double> x, std::span<double> r, std::span<double> jac) { m.evaluate(x, r, jac); },
      "held at rest");
  const std::vector<double> u = random_state(m, rng);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> rate(u.size()), moved(u.size());
  for (double& v : rate) v = 5.0 * unit(rng);
  const double cj = 3.7;
  expect_differences_match(
      m, u,
      [&](std::span<const double> x, std::span<double> r, std::span<double> jac) {
        for (std::size_t k = 0; k < x.size(); ++k) moved[k] = rate[k] + cj * (x[k] - u[k]);
        m.evaluate_in_time(x, moved, cj, r, jac);
      },
      "held at rest, in real time");
  // The held rows are the rigid body's own: a rate row reads its rate, a hold its distance.
  std::vector<double> r(u.size());
  m.evaluate_in_time(u, rate, cj, r, {});
  const std::vector<char> differential = m.rate_unknowns();
  const Index rigid = m.layout().blocks().front().offset;
  for (Index k = rigid; k < rigid + 4; ++k) {
    if (differential[std::size_t(k)]) {
      EXPECT_EQ(r[std::size_t(k)], rate[std::size_t(k)]) << "row " << k;
    }
  }
  m.hold_at_rest({});
  EXPECT_FALSE(m.held_at_rest());
}

// Newton's form at a root of a nearly unloaded washer (1 N), lifted off its film: the
// rows λ·p̂ with λ > 1 are there, and the Jacobian is exact (λ's own slope multiplies
// p̂ = 0).
TEST(NewtonFormJacobian, IsExactAtTheRootOfALiftedWasher) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 100.0);
  s.mesh.radial_nodes = 5;
  s.mesh.circumferential_nodes = 12;
  BearingModel m(s);
  SteadySolver solver(m, {});
  std::vector<double> u;
  ASSERT_TRUE(solver.solve_cold(u).converged);
  NaturalSettings down;
  down.initial_step = down.max_step = 20.0;
  const NaturalReport rep = continue_in_parameter(m, u, m.parameter(), 1.0, down);
  ASSERT_TRUE(rep.reached_target) << rep.message;
  const NewtonForm form(m);
  EXPECT_GT(lifted_pressure_rows(m, u), 0) << "no row of Newton's form with λ > 1: the test would not test it";
  expect_differences_match(
      m, u, [&](std::span<const double> x, std::span<double> r, std::span<double> jac) { m.evaluate(x, r, jac); },
      "Newton's form at 1 N");
}

// In real time (docs/physics.md section 19) the film's squeeze reads the rigid body's
// rates: IDA's iteration matrix ∂G/∂u + c_j·∂G/∂u' is the derivative in x of
// G(x, u'₀ + c_j·(x − u)) at x = u, the rates moving with the state as the BDF formula
// moves them; differenced so, at random rates, and with the gear's tilt turning. (The
// mass-conserving model has no squeeze: the duty cycle refuses it.)
TEST_P(JacobianTest, InRealTimeMatchesCentralDifferences) {
  const EffectSet e = GetParam();
  if (e.cavitation_model == CavitationModel::jfo || !e.hydro) GTEST_SKIP() << "no film squeeze";
  const std::unique_ptr<BearingModel> m = model_of(e);
  m->set_imposed_tilt_rate(2e-3);
  std::mt19937 rng(54321);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double cj = 3.7;  // 1/s: a BDF step of about a quarter second
  for (int trial = 0; trial < 2; ++trial) {
    const std::vector<double> u = random_state(*m, rng);
    std::vector<double> rate(u.size()), moved(u.size());
    for (double& v : rate) v = 5.0 * unit(rng);
    expect_differences_match(
        *m, u,
        [&](std::span<const double> x, std::span<double> r, std::span<double> jac) {
          for (std::size_t k = 0; k < x.size(); ++k) moved[k] = rate[k] + cj * (x[k] - u[k]);
          m->evaluate_in_time(x, moved, cj, r, jac);
        },
        std::string(e.name) + " in real time, trial " + std::to_string(trial));
  }
  // The consistent start's system (solver/consistent_rates.h): its unknowns are the
  // algebraic unknowns and the differential ones' rates, its Jacobian ∂G/∂y and ∂G/∂y' by
  // column, built from two of the model's matrices (c_j = 0 and 1).
  const std::vector<double> capacities = m->capacities();
  const std::vector<char> reads = m->rate_unknowns();
  std::vector<char> differential(capacities.size());
  for (std::size_t k = 0; k < differential.size(); ++k) differential[k] = capacities[k] > 0.0 || reads[k];
  const std::vector<double> u = random_state(*m, rng);
  std::vector<double> rate(u.size());
  for (double& v : rate) v = 5.0 * unit(rng);
  const ConsistentRates start(*m, u, capacities, differential, 0.4);
  expect_differences_match(
      *m, start.unknowns_of(u, rate),
      [&](std::span<const double> z, std::span<double> r, std::span<double> jac) { start.evaluate(z, r, jac); },
      std::string(e.name) + " consistent start");
}

INSTANTIATE_TEST_SUITE_P(
    EffectCombinations, JacobianTest,
    ::testing::Values(EffectSet{"contact_static", false, false, true, false, 0.0},
                      EffectSet{"contact_sliding", false, false, true, false, 545.0},
                      EffectSet{"contact_thermal", false, false, true, true, 545.0},
                      EffectSet{"hydro_contact", true, false, true, false, 545.0},
                      EffectSet{"hydro_factors_contact", true, true, true, false, 545.0},
                      EffectSet{"hydro_contact_thermal", true, false, true, true, 545.0},
                      EffectSet{"all_effects", true, true, true, true, 545.0},
                      EffectSet{"all_effects_slow", true, true, true, true, 136.0},
                      EffectSet{"all_effects_carrier_averaged", true, true, true, true, 545.0,
                                CarrierTemperature::axisymmetric},
                      EffectSet{"hydro_contact_minimum_row", true, false, true, false, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::minimum},
                      EffectSet{"all_effects_minimum_row", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::minimum},
                      EffectSet{"thermal_deformation", true, true, true, true, 545.0, CarrierTemperature::load_frame,
                                CavitationRow::fischer_burmeister, true},
                      EffectSet{"thermal_deformation_constant_friction", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::constant},
                      EffectSet{"thermal_deformation_contact_only", false, false, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true},
                      EffectSet{"thermal_deformation_carrier_averaged", true, true, true, true, 545.0,
                                CarrierTemperature::axisymmetric, CavitationRow::fischer_burmeister, true},
                      EffectSet{"jfo_all_effects", true, true, true, true, 545.0, CarrierTemperature::load_frame,
                                CavitationRow::fischer_burmeister, false, FrictionLaw::empirical,
                                CavitationModel::jfo},
                      EffectSet{"jfo_isothermal_minimum_row", true, false, true, false, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::minimum, false, FrictionLaw::empirical,
                                CavitationModel::jfo},
                      EffectSet{"jfo_with_deformation", true, true, true, true, 545.0, CarrierTemperature::load_frame,
                                CavitationRow::fischer_burmeister, true, FrictionLaw::empirical,
                                CavitationModel::jfo},
                      EffectSet{"grooved_sliding_film_all_effects", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::empirical, CavitationModel::reynolds, 2},
                      EffectSet{"grooved_standing_film_jfo", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, false,
                                FrictionLaw::empirical, CavitationModel::jfo, 1},
                      EffectSet{"fed_grooves_jfo", true, true, true, true, 545.0, CarrierTemperature::load_frame,
                                CavitationRow::fischer_burmeister, true, FrictionLaw::empirical,
                                CavitationModel::jfo, 2, true},
                      EffectSet{"fed_grooves_reynolds", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, false,
                                FrictionLaw::empirical, CavitationModel::reynolds, 2, true},
                      EffectSet{"convection", true, true, true, true, 545.0, CarrierTemperature::load_frame,
                                CavitationRow::fischer_burmeister, false, FrictionLaw::empirical,
                                CavitationModel::reynolds, 0, false, true},
                      EffectSet{"convection_fed_grooves_jfo_deformation", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::empirical, CavitationModel::jfo, 2, true, true},
                      EffectSet{"dammed_grooves_all_effects", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::empirical, CavitationModel::reynolds, 2, false, false, true},
                      EffectSet{"dammed_fed_grooves_convection_jfo", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, false,
                                FrictionLaw::empirical, CavitationModel::jfo, 2, true, true, true},
                      // A part of the gap from outside the model: alone (the contact force
                      // is an unknown without thermal deformation), and summed with it.
                      EffectSet{"prescribed_wear", true, true, true, true, 545.0, CarrierTemperature::load_frame,
                                CavitationRow::fischer_burmeister, false, FrictionLaw::empirical,
                                CavitationModel::reynolds, 0, false, false, false, true},
                      EffectSet{"prescribed_wear_deformation_fed_grooves_convection", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::empirical, CavitationModel::reynolds, 2, true, true, false, true},
                      // The worn faces' depths as a part of the sliding film's gap: on film 1,
                      // and on film 2 summed with thermal deformation's, by fed grooves.
                      EffectSet{"wear", true, true, true, true, 545.0, CarrierTemperature::load_frame,
                                CavitationRow::fischer_burmeister, false, FrictionLaw::empirical,
                                CavitationModel::reynolds, 0, false, false, false, false, true},
                      EffectSet{"wear_deformation_fed_grooves_convection", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::empirical, CavitationModel::reynolds, 2, true, true, false, false, true},
                      // Their roughness run in ([W5]-[W6]): σ per node from the depths.
                      EffectSet{"wear_running_in", true, true, true, true, 545.0, CarrierTemperature::load_frame,
                                CavitationRow::fischer_burmeister, false, FrictionLaw::empirical,
                                CavitationModel::reynolds, 0, false, false, false, false, true, true},
                      // The washer as a plate (section 21): its loads from both films, fluid and
                      // contact; with thermal deformation its thermal curvature from the heat
                      // crossing it; with contact alone; on faces that wear and run in, by
                      // fed grooves in film 2.
                      EffectSet{"elastic_washer", true, true, true, true, 545.0, CarrierTemperature::load_frame,
                                CavitationRow::fischer_burmeister, true, FrictionLaw::empirical,
                                CavitationModel::reynolds, 0, false, false, false, false, false, false, true},
                      EffectSet{"elastic_washer_without_thermal_curvature", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, false,
                                FrictionLaw::empirical, CavitationModel::reynolds, 0, false, false, false, false,
                                false, false, true},
                      EffectSet{"elastic_washer_contact_only", false, false, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::empirical, CavitationModel::reynolds, 0, false, false, false, false,
                                false, false, true},
                      EffectSet{"elastic_washer_wear_running_in", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::empirical, CavitationModel::reynolds, 0, false, false, false, false, true,
                                true, true},
                      EffectSet{"elastic_washer_jfo_fed_grooves_convection", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::empirical, CavitationModel::jfo, 2, true, true, false, false, false,
                                false, true},
                      // Its rigidity D(T) of the washer's temperature at each node (section 23).
                      EffectSet{"elastic_polymer_washer", true, true, true, true, 545.0,
                                CarrierTemperature::load_frame, CavitationRow::fischer_burmeister, true,
                                FrictionLaw::empirical, CavitationModel::reynolds, 0, false, false, false, false,
                                false, false, true, true}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace twb
