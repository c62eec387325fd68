// The stability suite (CTest label `stability`): the paper's bearing pushed to the
// edges of the legal input space (docs/scenes.md, "Bounds"), each case solved as one
// point and as a short load sweep through the study runner, as `twb run` does. Every
// run must end one of two ways (docs/reliability.md):
//  - solved: every state converged to the solver's tolerance with finite outputs, its
//    force, moment and energy balances met (tests/support/converged_balances.h) and its
//    fluid and contact shares summing to 1;
//  - a diagnosis: the study says it failed, naming what (a steady state at a load, or
//    distress) and where (the balance, film and node whose residual is largest).
// Never an exception, a NaN or inf in a result, or a hang (CTest's timeout bounds each
// case: tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../support/converged_balances.h"
#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "study/study_runner.h"

namespace twb {
namespace {

struct Case {
  std::string name;
  std::vector<std::string> overrides;  // on the paper's scene, on a 5×24 mesh unless they set one
  double load = 500.0;                 // N, the scene's
  // What the case reaches today (docs/reliability.md): a case solved must stay solved;
  // one that ends in a diagnosis may become solved (then update this and the docs).
  bool point_solved = true, sweep_solved = true;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<std::string> surfaces(const std::string& roughness) {
  std::vector<std::string> keys;
  for (const char* face : {"carrier", "washer", "gear"})
    for (const char* key : {"Ra", "Rq"}) keys.push_back(fmt::format("surfaces.{}.{}={}", face, key, roughness));
  return keys;
}

bool finite_state(const BearingState& s) {
  for (double v : {s.load, s.speed, s.washer_mean_temperature, s.max_film_temperature, s.hmin_over_sigma,
                   s.gamma_x_ratio, s.gamma_y_ratio, s.fluid_force, s.contact_force, s.fluid_share, s.contact_share,
                   s.torque, s.f_eff, s.stribeck, s.heat_generated, s.heat_to_ambient, s.energy_error,
                   s.force_balance_error, s.moment_balance_error, s.max_contact_pressure})
    if (!std::isfinite(v)) return false;
  return true;
}

// The solver's tolerance on the scaled residual (NewtonSettings' default, the scene's).
constexpr double kTolerance = 1e-10;

void expect_solved_or_diagnosed(const StudyOutcome& o, const std::string& what, bool solved_today = false) {
  SCOPED_TRACE(what);
  if (solved_today) {
    EXPECT_FALSE(o.solver_failed) << "solved before, now: " << o.message;
  }
  if (o.solver_failed) {
    // A diagnosis names what failed and, for a solver's failure, the balance and place.
    EXPECT_FALSE(o.message.empty());
    const bool names_place = o.message.find("balance") != std::string::npos ||
                             o.message.find("distress") != std::string::npos;
    EXPECT_TRUE(names_place) << "a failure must say which balance or that distress was reached: " << o.message;
    std::cout << "  " << what << ": diagnosis: " << o.message << "\n";
  } else {
    EXPECT_FALSE(o.states.empty());
    std::cout << "  " << what << ": " << o.states.size() << " states\n";
  }
  for (const SolvedState& r : o.states) {
    EXPECT_TRUE(finite_state(r.state)) << "a non-finite output at " << r.state.load << " N";
    if (!r.converged) {
      EXPECT_TRUE(o.solver_failed || !o.message.empty()) << "an unconverged state without a word at " << r.state.load;
      continue;
    }
    // At thousands of kelvin the heat rows' rounding exceeds 1e-10 K: the Newton solver
    // then accepts a stall within each row's rounding floor, and never above 1e3 times
    // the tolerance (KinsolNewton::within_rounding); the balances below still hold.
    EXPECT_LE(r.residual, 1e3 * kTolerance) << r.state.load << " N";
    testing::expect_balanced(r.state);
    // The sliding film carries the load by fluid and contact: the shares sum to 1 up to
    // the force balance (a film's force row, relative to the load).
    EXPECT_NEAR(r.state.fluid_share + r.state.contact_share, 1.0, 1e-8) << r.state.load << " N";
  }
  for (const DistressRow& d : o.distress) {
    if (d.distress_load) {
      EXPECT_TRUE(std::isfinite(*d.distress_load) && *d.distress_load > 0);
    }
  }
}

StudyOutcome run(const Case& c, const std::string& study) {
  std::vector<std::string> keys{"mesh.radial_nodes=5", "mesh.circumferential_nodes=24"};
  keys.insert(keys.end(), c.overrides.begin(), c.overrides.end());
  keys.push_back("study=" + study);
  const Scene scene = load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml", keys);
  BearingModel model(scene);
  return run_study(model, {});
}

class Stability : public ::testing::TestWithParam<Case> {};

TEST_P(Stability, AsAPoint) {
  const auto t0 = std::chrono::steady_clock::now();
  StudyOutcome o;
  ASSERT_NO_THROW(o = run(GetParam(), "{type: point}"));
  expect_solved_or_diagnosed(o, "point", GetParam().point_solved);
  std::cout << fmt::format("  {:.2f} s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

TEST_P(Stability, AsAShortSweep) {
  const Case& c = GetParam();
  const std::string study =
      fmt::format("{{type: load_sweep, load_start: {} N, load_end: {} N, load_steps: 3, error_estimate: none}}",
                  0.5 * c.load, c.load);
  StudyOutcome o;
  ASSERT_NO_THROW(o = run(c, study));
  expect_solved_or_diagnosed(o, "sweep", c.sweep_solved);
}

const Case kCases[] = {
    {"at_rest", {"operating.speed=0 rad/s"}},
    {"creeping", {"operating.speed=1e-3 rad/s"}},
    {"fast", {"operating.speed=10000 rad/s"}},
    {"featherweight", {"operating.load=0.01 N"}, 0.01, false, false},
    {"heavy", {"operating.load=50 kN"}, 50000.0, false, true},
    {"untilted", {"geometry.gear.tilt=0 rad"}},
    {"steeply_tilted", {"geometry.gear.tilt=50 mrad"}},
    {"polished", surfaces("0.01 um"), 500.0, false, false},
    {"rough", surfaces("10 um")},
    {"frictionless", {"friction={law: constant, coefficient: 0}"}},
    {"grippy", {"friction={law: constant, coefficient: 1.5}"}},
    {"thin_oil", {"lubricant.viscosity={model: constant, value: 1e-5 Pa s}"}},
    {"thick_oil", {"lubricant.viscosity={model: constant, value: 10 Pa s}"}},
    {"freezing", {"operating.ambient=-30 degC"}},
    {"hot_sump", {"operating.ambient=150 degC"}},
    {"coarsest_mesh", {"mesh.radial_nodes=3", "mesh.circumferential_nodes=8"}},
    {"washer_on_gear", {"operating.sliding=washer_gear"}},
    {"cold_start_far_open", {"solver.cold_start_film=100"}},
    {"cold_start_far_closed", {"solver.cold_start_film=0.3"}},
};
INSTANTIATE_TEST_SUITE_P(Edges, Stability, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& i) { return i.param.name; });

// The finest mesh the work-precision study uses, as a point on the hot branch (500 N:
// 57-64 s alone on a CI-like machine; the sweep would repeat it three times).
TEST(StabilityFineMesh, PointOn65x528) {
  StudyOutcome o;
  ASSERT_NO_THROW(o = run({"fine_mesh", {"mesh.radial_nodes=65", "mesh.circumferential_nodes=528"}},
                          "{type: point}"));
  expect_solved_or_diagnosed(o, "point on 65x528", true);
}

// Loads 0.1 % either side of W_d on the suite's mesh: the cold start must land on a
// steady state (cool below, hot above: both are steady states) or say why.
TEST(StabilityAtDistress, PointsJustEitherSideOfTheFold) {
  const StudyOutcome sweep = run({"locate", {}}, "{type: load_sweep, load_start: 100 N, load_end: 400 N, "
                                                 "load_steps: 2, error_estimate: none}");
  ASSERT_FALSE(sweep.distress.empty());
  ASSERT_TRUE(sweep.distress.front().distress_load.has_value());
  const double w_d = *sweep.distress.front().distress_load;
  for (double factor : {0.999, 1.001}) {
    const double load = factor * w_d;
    const Case c{fmt::format("W_d x {}", factor), {fmt::format("operating.load={:.10g} N", load)}, load};
    StudyOutcome o;
    ASSERT_NO_THROW(o = run(c, "{type: point}"));
    expect_solved_or_diagnosed(o, c.name, true);
  }
}

}  // namespace
}  // namespace twb
