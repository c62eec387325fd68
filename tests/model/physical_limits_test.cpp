// Limits the coupled model must reproduce whatever its discretization, checked on
// solved states (docs/physics.md sections 1, 3 and 7):
//   a. contact only, no speed: the washer settles mirror-symmetric, γy = γ_tilt/2, γx = 0;
//   b. the unknowns are exactly those of the enabled effects;
//   c. temperatures that do not feed back (constant viscosity) leave the mechanics
//      untouched, even though the bearing heats up;
//   d. Patir–Cheng flow factors reduce to classic Reynolds as σ → 0.
//
// Tolerances refer to the solver's: the max-norm of the scaled residual is driven below
// 1e-10 (NewtonSettings' default), where force rows are fractions of the load, moment
// rows fractions of F_ext·r_o and heat rows kelvin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "solver/kinsol_newton.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

constexpr double kSolverTolerance = 1e-10;  // NewtonSettings{}.residual_tolerance

NewtonSettings settings() {
  NewtonSettings s;
  EXPECT_EQ(s.residual_tolerance, kSolverTolerance);
  return s;
}

// Largest change of the scaled residual when u moves by a few ulps: the rounding floor
// below which no solver can drive the residual. Reported when a solve fails.
double residual_rounding_floor(const BearingModel& m, const std::vector<double>& u) {
  std::vector<double> r0(u.size()), r1(u.size()), v = u;
  m.evaluate(u, r0, {});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  for (double& x : v) x *= 1.0 + 4e-16 * d(rng);
  m.evaluate(v, r1, {});
  double floor = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) floor = std::max(floor, std::abs(r1[k] - r0[k]));
  return floor;
}

// ---------------------------------------------------------------------------------
// a. Contact only, zero speed.
//
// docs/physics.md section 1: with no lift the washer takes the mirror-symmetric position
// γy = γ_tilt/2 (the continuum answer differs from 0.5 by < 2e-7 because film 1 also
// touches a little inside the gear's inner radius), and γx = 0 by the symmetry y → −y.
// Contact is integrated over each cell on the exact plane, so the answer must not
// depend on the mesh: 1e-6 leaves a factor 5 over the continuum deviation and is far
// above what the solver tolerance allows (1e-10 on moment rows of order 1 per unit of
// γ/γ_tilt). γx has no source at all on a mesh symmetric in θ → −θ: only the solver's
// 1e-10 residual (times a moment stiffness of order 1 in these units) can move it,
// hence 1e-9. Balance rows ARE the scaled residual rows, so they are below the solver
// tolerance; 1e-8 is what the brief asks and leaves two decades.
struct StaticCase {
  int radial, circumferential;
  double load;
};

class ContactOnlyStatic : public ::testing::TestWithParam<StaticCase> {};

TEST_P(ContactOnlyStatic, WasherSettlesMirrorSymmetric) {
  const StaticCase c = GetParam();
  Scene s = testing::table1_scene(false, false, true, false, 0.0, c.load);
  s.mesh.radial_nodes = c.radial;
  s.mesh.circumferential_nodes = c.circumferential;
  BearingModel m(s);
  SteadySolver solver(m, settings());
  std::vector<double> u;
  const SteadyReport rep = solver.solve_cold(u);
  ASSERT_TRUE(rep.converged) << rep.message;
  const BearingState st = m.describe(u);
  std::cout << "[ static ] " << c.radial << "x" << c.circumferential << " " << c.load
            << " N: gamma_y/tilt - 0.5 = " << st.gamma_y_ratio - 0.5 << ", gamma_x/tilt = " << st.gamma_x_ratio
            << ", h_min/sigma = " << st.hmin_over_sigma << ", " << rep.iterations << " iterations, " << rep.wall_ms
            << " ms\n";
  EXPECT_NEAR(st.gamma_y_ratio, 0.5, 1e-6);
  EXPECT_NEAR(st.gamma_x_ratio, 0.0, 1e-9);
  EXPECT_LT(st.force_balance_error, 1e-8);
  EXPECT_LT(st.moment_balance_error, 1e-8);
  // Without speed there is no fluid film and nothing but contact carries the load.
  EXPECT_NEAR(st.contact_share, 1.0, 1e-8);
  EXPECT_EQ(st.fluid_share, 0.0);
}

std::vector<StaticCase> static_cases() {
  std::vector<StaticCase> v;
  for (auto [nr, nt] : {std::pair{9, 66}, std::pair{5, 24}, std::pair{17, 132}})
    for (double load : {200.0, 500.0, 1000.0}) v.push_back({nr, nt, load});
  return v;
}

INSTANTIATE_TEST_SUITE_P(PaperAndOtherMeshes, ContactOnlyStatic, ::testing::ValuesIn(static_cases()),
                         [](const auto& info) {
                           return "mesh" + std::to_string(info.param.radial) + "x" +
                                  std::to_string(info.param.circumferential) + "_" +
                                  std::to_string(int(info.param.load)) + "N";
                         });

// ---------------------------------------------------------------------------------
// b. Unknown counts per effect (docs/physics.md sections 1, 3, 7; exact integers, no tolerance).
//
// From docs/physics.md: 4 rigid-body unknowns always; the pressure only on the sliding film, at
// the nodes not on its two radial edges (p = 0 there); with thermal, a film-node
// temperature at every node of both films, the carrier T(r, θ) (fixed in the load
// frame), the gear T(r) (it always rotates), the washer T(r) when it rotates with the
// gear (film 1 slides) and T(r, θ) when it is stuck to the carrier (film 2 slides).
// Flow factors and contact add no unknowns.
struct Expected {
  Index rigid = 4, pressure = 0, film_temperature = 0, carrier = 0, washer = 0, gear = 0;
  Index total() const { return rigid + pressure + film_temperature + carrier + washer + gear; }
};

Expected expected_unknowns(const Scene& s) {
  const Index nr = s.mesh.radial_nodes, nt = s.mesh.circumferential_nodes;
  const bool film1_slides = s.operating.sliding == SlidingFilm::carrier_washer;
  Expected e;
  if (s.effects.hydrodynamics) e.pressure = (nr - 2) * nt;
  if (s.effects.thermal) {
    e.film_temperature = 2 * nr * nt;
    e.carrier = nr * nt;
    e.washer = film1_slides ? nr : nr * nt;
    e.gear = nr;
  }
  return e;
}

const UnknownBlock* find_block(const UnknownLayout& layout, const std::string& name_part) {
  const UnknownBlock* found = nullptr;
  for (const UnknownBlock& b : layout.blocks())
    if (b.name.find(name_part) != std::string::npos) {
      EXPECT_EQ(found, nullptr) << "two blocks named like '" << name_part << "'";
      found = &b;
    }
  return found;
}

Index block_total(const UnknownLayout& layout, BlockEffect effect) {
  Index n = 0;
  for (const UnknownBlock& b : layout.blocks())
    if (b.effect == effect) n += b.size;
  return n;
}

TEST(UnknownCounts, MatchModelForEveryEffectCombination) {
  for (auto [nr, nt] : {std::pair{9, 66}, std::pair{5, 12}})
    for (SlidingFilm sliding : {SlidingFilm::carrier_washer, SlidingFilm::washer_gear})
      for (int bits = 0; bits < 16; ++bits) {
        const bool hydro = bits & 1, factors = bits & 2, contact = bits & 4, thermal = bits & 8;
        if (factors && !hydro) continue;  // flow factors modify the Reynolds equation only
        Scene s = testing::table1_scene(hydro, factors, contact, thermal, 545.0, 500.0);
        s.mesh.radial_nodes = nr;
        s.mesh.circumferential_nodes = nt;
        s.operating.sliding = sliding;
        const int sliding_number = sliding == SlidingFilm::carrier_washer ? 1 : 2;
        const int other_number = 3 - sliding_number;
        const std::string label = std::to_string(nr) + "x" + std::to_string(nt) + " film " +
                                  std::to_string(sliding_number) + " slides, hydro " + std::to_string(hydro) +
                                  " factors " + std::to_string(factors) + " contact " + std::to_string(contact) +
                                  " thermal " + std::to_string(thermal);
        SCOPED_TRACE(label);
        const BearingModel m(s);
        const UnknownLayout& layout = m.layout();
        const Expected e = expected_unknowns(s);

        // Blocks tile [0, size) in order, and size() is their sum.
        Index next = 0;
        for (const UnknownBlock& b : layout.blocks()) {
          EXPECT_EQ(b.offset, next) << b.name;
          EXPECT_GT(b.size, 0) << b.name << ": an empty block";
          next += b.size;
        }
        EXPECT_EQ(next, m.size());
        EXPECT_EQ(m.size(), e.total());

        EXPECT_EQ(block_total(layout, BlockEffect::mechanics), e.rigid);
        EXPECT_EQ(block_total(layout, BlockEffect::hydrodynamics), e.pressure);
        EXPECT_EQ(block_total(layout, BlockEffect::thermal), e.film_temperature + e.carrier + e.washer + e.gear);
        for (const UnknownBlock& b : layout.blocks())
          EXPECT_TRUE(b.effect == BlockEffect::mechanics || b.effect == BlockEffect::hydrodynamics || b.effect == BlockEffect::thermal)
              << "block '" << b.name << "' of unexpected effect '" << effect_name(b.effect) << "'";

        // Pressure on the sliding film only.
        const UnknownBlock* p_slide = find_block(layout, "film " + std::to_string(sliding_number) + " pressure");
        const UnknownBlock* p_other = find_block(layout, "film " + std::to_string(other_number) + " pressure");
        EXPECT_EQ(p_other, nullptr) << "pressure on the non-sliding film";
        EXPECT_LT(m.films()[other_number - 1].pressure_offset, 0);
        if (hydro) {
          ASSERT_NE(p_slide, nullptr);
          EXPECT_EQ(p_slide->size, e.pressure);
          EXPECT_EQ(m.films()[sliding_number - 1].pressure_offset, p_slide->offset);
        } else {
          EXPECT_EQ(p_slide, nullptr);
          EXPECT_LT(m.films()[sliding_number - 1].pressure_offset, 0);
        }

        // Temperatures.
        const UnknownBlock* carrier = find_block(layout, "carrier temperature");
        const UnknownBlock* washer = find_block(layout, "washer temperature");
        const UnknownBlock* gear = find_block(layout, "gear temperature");
        if (!thermal) {
          EXPECT_EQ(carrier, nullptr);
          EXPECT_EQ(washer, nullptr);
          EXPECT_EQ(gear, nullptr);
          EXPECT_TRUE(m.components().empty());
          for (const Film& f : m.films()) EXPECT_LT(f.temperature_offset, 0);
          continue;
        }
        ASSERT_NE(carrier, nullptr);
        ASSERT_NE(washer, nullptr);
        ASSERT_NE(gear, nullptr);
        EXPECT_EQ(carrier->size, e.carrier);
        EXPECT_EQ(washer->size, e.washer);
        EXPECT_EQ(gear->size, e.gear);
        // The washer is T(r, θ) exactly when it is stuck to the carrier.
        const bool washer_polar = sliding == SlidingFilm::washer_gear;
        EXPECT_EQ(washer->name.find("T(r, theta)") != std::string::npos, washer_polar) << washer->name;
        EXPECT_NE(carrier->name.find("T(r, theta)"), std::string::npos) << carrier->name;
        EXPECT_EQ(gear->name.find("theta"), std::string::npos) << gear->name;
        for (const ComponentHeat& c : m.components()) {
          if (c.id == ComponentId::washer) {
            EXPECT_EQ(c.axisymmetric, !washer_polar);
          } else if (c.id == ComponentId::carrier) {
            EXPECT_FALSE(c.axisymmetric);
          } else {
            EXPECT_TRUE(c.axisymmetric);
          }
        }
        for (int f = 1; f <= 2; ++f) {
          const UnknownBlock* tf = find_block(layout, "film " + std::to_string(f) + " film-node temperature");
          ASSERT_NE(tf, nullptr);
          EXPECT_EQ(tf->size, Index(nr) * nt);
        }
      }
}

TEST(UnknownCounts, TotalDropsByTheEffectsBlocksWhenItIsOff) {
  for (SlidingFilm sliding : {SlidingFilm::carrier_washer, SlidingFilm::washer_gear}) {
    auto size_of = [&](bool hydro, bool factors, bool contact, bool thermal) {
      Scene s = testing::table1_scene(hydro, factors, contact, thermal, 545.0, 500.0);
      s.operating.sliding = sliding;
      return BearingModel(s).size();
    };
    const Index all = size_of(true, true, true, true);
    const Index nr = 9, nt = 66;
    const Index washer = sliding == SlidingFilm::carrier_washer ? nr : nr * nt;
    const Index thermal_unknowns = 2 * nr * nt + nr * nt + washer + nr;
    EXPECT_EQ(all - size_of(false, false, true, true), (nr - 2) * nt) << "hydrodynamics off";
    EXPECT_EQ(all - size_of(true, true, true, false), thermal_unknowns) << "thermal off";
    EXPECT_EQ(all - size_of(false, false, true, false), (nr - 2) * nt + thermal_unknowns) << "both off";
    EXPECT_EQ(size_of(false, false, true, false), 4) << "mechanics alone";
    EXPECT_EQ(all, size_of(true, false, true, true)) << "flow factors add no unknowns";
    EXPECT_EQ(all, size_of(true, true, false, true)) << "contact adds no unknowns";
  }
}

// ---------------------------------------------------------------------------------
// c. Thermal off = thermal on when temperature cannot feed back.
//
// No scene key turns viscous heating off, and zero speed would remove the fluid film
// too, so the comparison is made at speed: with a constant viscosity nothing mechanical
// depends on temperature (docs/physics.md sections 3-6: the film is a rigid plane, friction
// depends on contact force only, μ is the only coupling), so scene B (thermal) must
// reproduce scene A's mechanical state although B heats up. Both are solved to scaled
// residuals ≤ 1e-10 in the same mechanical and Reynolds rows; the rigid-body rows are
// fractions of the load with stiffness O(1) per σ or per γ_tilt in the scaled unknowns
// (mixed film, h_min/σ ≈ 1.6), so positions agree to ~1e-10 of σ, i.e. relatively
// to ~1e-11 of the clearance and ~1e-10 of γ_tilt: 1e-8 leaves two decades.
// Shares are fractions of the load (rows with the solver tolerance): 1e-8 absolute.
// Torque and heat are integrals of the same fields: 1e-8 relative.
struct ThermalCase {
  const char* name;
  FrictionLaw law;
  double coefficient;
};

class ThermalDecoupled : public ::testing::TestWithParam<ThermalCase> {};

TEST_P(ThermalDecoupled, ConstantViscosityLeavesMechanicsUnchanged) {
  const ThermalCase c = GetParam();
  auto scene = [&](bool thermal) {
    Scene s = testing::table1_scene(true, true, true, thermal, 953.0, 700.0);
    s.lubricant.viscosity_model = ViscosityModel::constant;
    s.lubricant.constant_viscosity = 0.06081;  // μ0 = Roelands at the 24 °C ambient
    s.friction.law = c.law;
    s.friction.coefficient = c.coefficient;
    return s;
  };
  BearingModel a(scene(false)), b(scene(true));
  ASSERT_GT(b.size(), a.size());
  std::vector<double> ua, ub;
  const SteadyReport ra = SteadySolver(a, settings()).solve_cold(ua);
  const SteadyReport rb = SteadySolver(b, settings()).solve_cold(ub);
  ASSERT_TRUE(ra.converged) << ra.message;
  ASSERT_TRUE(rb.converged) << rb.message;
  const BearingState sa = a.describe(ua), sb = b.describe(ub);
  std::cout << "[ thermal ] " << c.name << ": A " << ra.wall_ms << " ms, B " << rb.wall_ms
            << " ms; B heats " << sb.heat_generated << " W, washer +" << sb.washer_mean_temperature - 297.15
            << " K, hottest film node +" << sb.max_film_temperature - 297.15 << " K, energy error "
            << sb.energy_error << "; dc1/c1 " << (sb.position.c1 - sa.position.c1) / sa.position.c1
            << ", dgx/tilt " << sb.gamma_x_ratio - sa.gamma_x_ratio << ", dtorque/torque "
            << (sb.torque - sa.torque) / sa.torque << "\n";

  // B really heats up: otherwise the comparison would be vacuous.
  EXPECT_GT(sb.heat_generated, 0.1);
  EXPECT_GT(sb.washer_mean_temperature - b.scene().operating.ambient, 0.1);
  // Steady energy balance to the solver's tolerance: heat rows are kelvin ≤ 1e-10
  // times a node conductance, summed over nodes that carry the total conductance, so
  // the relative error is ≲ 1e-10 K over a mean rise of ≥ 0.1 K: 1e-8.
  EXPECT_LT(sb.energy_error, 1e-8);

  const double tilt = a.scene().gear.tilt;
  EXPECT_NEAR(sb.position.c1, sa.position.c1, 1e-8 * std::abs(sa.position.c1));
  EXPECT_NEAR(sb.position.c2, sa.position.c2, 1e-8 * std::abs(sa.position.c2));
  EXPECT_NEAR(sb.position.gamma_x, sa.position.gamma_x, 1e-8 * tilt);
  EXPECT_NEAR(sb.position.gamma_y, sa.position.gamma_y, 1e-8 * tilt);
  EXPECT_NEAR(sb.fluid_share, sa.fluid_share, 1e-8);
  EXPECT_NEAR(sb.contact_share, sa.contact_share, 1e-8);
  EXPECT_NEAR(sb.hmin_over_sigma, sa.hmin_over_sigma, 1e-8 * sa.hmin_over_sigma);
  EXPECT_NEAR(sb.torque, sa.torque, 1e-8 * sa.torque);
  // Heat generation is a function of the mechanics and μ only.
  EXPECT_NEAR(sb.heat_generated, sa.heat_generated, 1e-8 * sa.heat_generated);
}

INSTANTIATE_TEST_SUITE_P(FrictionLaws, ThermalDecoupled,
                         ::testing::Values(ThermalCase{"viscous_heat_only", FrictionLaw::constant, 0.0},
                                           ThermalCase{"empirical_friction", FrictionLaw::empirical, 0.0}),
                         [](const auto& info) { return std::string(info.param.name); });

// At zero speed no heat is generated at all (docs/physics.md section 6: q ∝ V), so with the
// Roelands oil the thermal scene must stay at ambient and equal the isothermal one.
// Temperatures are unknowns in kelvin with rows in kelvin: ≤ 1e-10 K from the solver,
// 1e-8 K leaves two decades.
TEST(ThermalDecoupledAtRest, NoSpeedNoHeatAmbientEverywhere) {
  BearingModel a(testing::table1_scene(false, false, true, false, 0.0, 500.0));
  BearingModel b(testing::table1_scene(false, false, true, true, 0.0, 500.0));
  std::vector<double> ua, ub;
  const SteadyReport ra = SteadySolver(a, settings()).solve_cold(ua);
  const SteadyReport rb = SteadySolver(b, settings()).solve_cold(ub);
  ASSERT_TRUE(ra.converged) << ra.message;
  ASSERT_TRUE(rb.converged) << rb.message;
  const BearingState sa = a.describe(ua), sb = b.describe(ub);
  EXPECT_EQ(sb.heat_generated, 0.0);
  for (const UnknownBlock& blk : b.layout().blocks())
    if (blk.effect == BlockEffect::thermal) {
      for (Index k = blk.offset; k < blk.offset + blk.size; ++k) ASSERT_NEAR(ub[k], 0.0, 1e-8) << blk.name;
    }
  EXPECT_NEAR(sb.washer_mean_temperature, b.scene().operating.ambient, 1e-8);
  EXPECT_NEAR(sb.position.c1, sa.position.c1, 1e-8 * sa.position.c1);
  EXPECT_NEAR(sb.position.gamma_y, sa.position.gamma_y, 1e-8 * a.scene().gear.tilt);
}

// At rest nothing slides (docs/physics.md section 9): the contacts carry the load, but
// their friction is static and dissipates nothing, so the running torque and f_eff are
// nought, not μ times the contact torque. Turning the washer at all (a thousandth of a
// rad/s, where the film carries nothing yet) gives that torque back: the nought is the
// rest's, not a torque left uncomputed. Eq [43] divides the torque by the mean radius of a
// uniform pressure, so with every contact between the washer's radii f_eff/μ lies
// between r_i and r_o times 1.5(r_o² − r_i²)/(r_o³ − r_i³): 0.632 and 1.292 here.
TEST(ThermalDecoupledAtRest, AtRestTheRunningTorqueAndFEffAreNought) {
  BearingModel still(testing::table1_scene(false, false, true, true, 0.0, 500.0));
  BearingModel turning(testing::table1_scene(false, false, true, true, 1e-3, 500.0));
  std::vector<double> us, ut;
  ASSERT_TRUE(SteadySolver(still, settings()).solve_cold(us).converged);
  ASSERT_TRUE(SteadySolver(turning, settings()).solve_cold(ut).converged);
  const BearingState s = still.describe(us), t = turning.describe(ut);
  EXPECT_GT(s.contact_force, 0.99 * 500.0);
  EXPECT_EQ(s.torque, 0.0);
  EXPECT_EQ(s.f_eff, 0.0);
  EXPECT_EQ(s.heat_generated, 0.0);
  const Scene& sc = turning.scene();
  const double ri = sc.washer.inner_radius, ro = sc.washer.outer_radius;
  const double per_radius = 1.5 * (ro * ro - ri * ri) / (ro * ro * ro - ri * ri * ri);
  EXPECT_GT(t.torque, 0.0);
  EXPECT_GE(t.f_eff, ri * per_radius * t.friction_coefficient);
  EXPECT_LE(t.f_eff, ro * per_radius * t.friction_coefficient);
}

// ---------------------------------------------------------------------------------
// d. Flow factors → classic Reynolds as σ → 0.
//
// docs/physics.md section 3: φx = φy = 1 − 0.9·exp(−0.56 h/σ), φs ≡ 0 for identical
// roughness, h̄T = h + O(σ·exp(−H²/2)); so at fixed film the difference between the
// averaged and the classic Reynolds equation falls like exp(−0.56 h_min/σ). At
// 1367 rad/s and 150 N the film is full (h_min/σ ≈ 12 at the paper's σ, no contact):
// shrinking σ five- and twenty-five-fold makes h_min/σ ≳ 60, where exp(−0.56 H) <
// 1e-14, so the two models must agree to the solver's accuracy. The difference is
// measured on the mechanical state: relative clearances, tilts in units of γ_tilt and
// the relative torque (the fluid force itself equals the load in both, by the force
// balance, once contact vanishes). It must shrink with σ until it reaches the solver's
// floor, taken as 1e-8: a residual ≤ 1e-10 in rows of stiffness ≳ 1e-2 per σ (thick
// film: ∂(F/F_ext)/∂(c/σ) ≈ 3σ/h) moves c by ≲ 1e-8 σ, far below 1e-8 of c itself.
// At the smallest σ the difference must be below 1e-6: the flow factors' own departure
// from 1 there is < 1e-40, so 1e-6 only has to absorb the solver's floor, and it is
// still below the ~1e-5 the factors make at the paper's σ, so the check can fail.
//
// The first σ is solved from the cold start (SteadySolver); each smaller σ warm-starts
// Newton from the previous solution (physical position and pressures carried over; the
// scaled unknowns change with σ), which is continuation, not a change of tolerance.
// σ is lowered by factors ≤ 2.5 (Rq 0.515, 0.25, 0.1, 0.05, 0.02 µm): a direct jump by 5
// fails (at the old position film 2's contact lies below its cutoff, so the Jacobian is
// singular, KIN_LSETUP_FAIL), and SteadySolver::solve's fallbacks would spend minutes.
Scene smooth_scene(bool flow_factors, double rq) {
  Scene s = testing::table1_scene(true, flow_factors, true, false, 1367.0, 150.0);
  s.carrier.roughness.rq = s.washer.roughness.rq = s.gear.roughness.rq = rq;
  const double sigma = std::hypot(rq, rq);
  s.asperities.summit_sigma = sigma;
  s.asperities.summit_density = s.asperities.eta_r_sigma / (s.asperities.summit_radius * sigma);
  return s;
}

struct SmoothSolution {
  BearingState state;
  bool converged = false;
};

std::vector<SmoothSolution> solve_sigma_path(bool flow_factors, const std::vector<double>& rqs) {
  std::vector<SmoothSolution> out;
  std::unique_ptr<BearingModel> prev_model;
  std::vector<double> prev;
  for (double rq : rqs) {
    auto m = std::make_unique<BearingModel>(smooth_scene(flow_factors, rq));
    std::vector<double> u;
    SmoothSolution sol;
    double residual = 0.0;
    if (!prev_model) {
      const SteadyReport rep = SteadySolver(*m, settings()).solve_cold(u);
      sol.converged = rep.converged;
      residual = rep.residual_norm;
    } else {
      u = m->cold_start();
      const RigidPosition q = prev_model->position(prev);
      u[0] = q.c1 / m->clearance_scale();
      u[1] = q.gamma_x / m->tilt_scale();
      u[2] = q.gamma_y / m->tilt_scale();
      u[3] = q.c2 / m->clearance_scale();
      for (std::size_t k = 4; k < u.size(); ++k) u[k] = prev[k] * prev_model->pressure_scale() / m->pressure_scale();
      KinsolNewton newton(*m);
      NewtonSettings ns = settings();
      ns.max_iterations = 60;  // a warm start; the cold start needs ~20
      const NewtonReport rep = newton.solve(u, ns);
      sol.converged = rep.converged;
      residual = rep.residual_norm;
    }
    sol.state = m->describe(u);
    EXPECT_TRUE(sol.converged) << "flow factors " << flow_factors << ", Rq = " << rq
                               << " m: not converged, scaled residual " << residual << " (tolerance "
                               << kSolverTolerance << "); rounding floor of the residual at this state "
                               << residual_rounding_floor(*m, u) << ", h_min/sigma " << sol.state.hmin_over_sigma;
    out.push_back(sol);
    prev = u;
    prev_model = std::move(m);
  }
  return out;
}

double mechanical_difference(const BearingState& a, const BearingState& b) {
  return std::max({std::abs(a.position.c1 - b.position.c1) / std::abs(b.position.c1),
                   std::abs(a.position.c2 - b.position.c2) / std::abs(b.position.c2),
                   std::abs(a.gamma_x_ratio - b.gamma_x_ratio), std::abs(a.gamma_y_ratio - b.gamma_y_ratio),
                   std::abs(a.torque - b.torque) / std::abs(b.torque)});
}

TEST(FlowFactorsSmoothLimit, RecoverClassicReynoldsAsSigmaVanishes) {
  const std::vector<double> rqs{0.515e-6, 0.25e-6, 0.1e-6, 0.05e-6, 0.02e-6};
  const std::vector<SmoothSolution> with = solve_sigma_path(true, rqs);
  const std::vector<SmoothSolution> without = solve_sigma_path(false, rqs);
  ASSERT_EQ(with.size(), rqs.size());
  std::vector<double> diff, fluid_diff;
  for (std::size_t k = 0; k < rqs.size(); ++k) {
    diff.push_back(mechanical_difference(with[k].state, without[k].state));
    fluid_diff.push_back(std::abs(with[k].state.fluid_force - without[k].state.fluid_force) /
                         without[k].state.fluid_force);
    std::cout << "[ smooth ] Rq " << rqs[k] << " m: h_min/sigma " << with[k].state.hmin_over_sigma
              << ", contact share " << with[k].state.contact_share << ", mechanical difference " << diff[k]
              << ", fluid force difference " << fluid_diff[k] << "\n";
    ::testing::Test::RecordProperty("mechanical_difference_rq_" + std::to_string(k), std::to_string(diff[k]));
  }
  // At the paper's σ the factors matter (otherwise the test would prove nothing).
  EXPECT_GT(diff[0], 1e-8);
  const double floor = 1e-8;
  for (std::size_t k = 1; k < rqs.size(); ++k) {
    EXPECT_TRUE(diff[k] < diff[k - 1] || diff[k] < floor)
        << "difference grew from " << diff[k - 1] << " to " << diff[k] << " as Rq fell to " << rqs[k];
    EXPECT_TRUE(fluid_diff[k] <= fluid_diff[k - 1] || fluid_diff[k] < floor)
        << "fluid force difference grew from " << fluid_diff[k - 1] << " to " << fluid_diff[k];
  }
  EXPECT_LT(diff.back(), 1e-6);
  EXPECT_LT(fluid_diff.back(), 1e-6);
}

}  // namespace
}  // namespace twb
