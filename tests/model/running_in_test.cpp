// Running-in of the sliding film's faces fed to the bearing (docs/physics.md section 20,
// [W5], [W6], [W8]): every kernel that reads σ or the summits reads each point's, from
// the worn depths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "../support/table1_scene.h"
#include "model/assembly_totals.h"
#include "model/bearing_model.h"
#include "model/wear_effect.h"
#include "physics/running_in.h"
#include "study/searches/steady_solver.h"
#include "study/study_runner.h"
#include "twb/scene/scene_loader.h"
#include "twb/study/study_outcome.h"

namespace twb {
namespace {

constexpr double kRunIn = 0.4;  // each face runs in to 0.4 of its Rq

// The paper's washer at 300 N on the coarse mesh with its oil, contact and heat; film 1
// slides (carrier at rest, washer turning).
Scene new_washer() {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 300.0);
  testing::use_coarse_mesh(s);
  return s;
}

const UnknownBlock* block_named(const BearingModel& m, const std::string& name) {
  for (const UnknownBlock& b : m.layout().blocks())
    if (b.name == name) return &b;
  return nullptr;
}

// Past its run-in depth a face has its run-in Rq everywhere, so to the sliding film a
// washer whose two sliding faces are worn uniformly past theirs is a washer of that
// roughness: σ the run-in faces' at every point, the summits scaled by k = σ_run-in/σ0
// (σs·k, R/k, η kept: §4's scaling), and the gap opened by the depths. So at the same gap,
// pressures and temperatures, everything the sliding film integrates (its contact force
// and friction power per node, its viscous heat and torque, the oil it
// passes at the rim through the flow factors) is a new washer's with Rq = run_in_rq and
// those summits. (The other film keeps its faces and the one population both films
// share: the two bearings differ there, and so in their solved states, which is why the
// check is at one state.) What differs is arithmetic: the scaled contact at its least
// table is that table (the interpolation's weights there are 1 and 0) reached through ln
// and exp, and the new washer integrates its flat cells on the flat rule (exact to 1e-15,
// contact_cell.cpp): 1e-12 of each quantity. The same state read with the faces' new Rq
// differs by more than a thousandth of each (the rim's oil flow by 0.4 %, the contact force
// by hundreds of times), so the check can fail.
TEST(RunningIn, ToTheSlidingFilmAWasherRunInIsANewWasherOfItsRunInRoughness) {
  Scene worn_scene = new_washer();
  worn_scene.effects.wear = true;
  for (Component* c : {&worn_scene.carrier, &worn_scene.washer, &worn_scene.gear}) c->roughness.wear_rate = 1e-17;
  for (Component* c : {&worn_scene.carrier, &worn_scene.washer}) c->roughness.run_in_rq = kRunIn * c->roughness.rq;
  BearingModel worn(worn_scene);
  // Each face (film 1: the carrier at rest, the washer turning) twice as deep as where it
  // runs in, uniformly.
  const double rest_depth = 2.0 * *RunningIn(worn_scene.carrier.roughness.rq, worn_scene.carrier.roughness.run_in_rq)
                                      .run_in_depth();
  const double turn_depth =
      2.0 * *RunningIn(worn_scene.washer.roughness.rq, worn_scene.washer.roughness.run_in_rq).run_in_depth();
  const FilmMesh& mesh = worn.sliding_film().mesh;
  worn.effect<WearEffect>()->hold(std::vector<double>(std::size_t(mesh.node_count()), rest_depth),
                                  std::vector<double>(std::size_t(mesh.radial_nodes()), turn_depth));
  std::vector<double> u_worn;
  ASSERT_TRUE(SteadySolver(worn, {}).solve_cold(u_worn).converged);

  Scene smooth = new_washer();
  const double k = std::hypot(kRunIn * smooth.carrier.roughness.rq, kRunIn * smooth.washer.roughness.rq) /
                   std::hypot(smooth.carrier.roughness.rq, smooth.washer.roughness.rq);
  for (Component* c : {&smooth.carrier, &smooth.washer}) c->roughness.rq *= kRunIn;
  smooth.asperities.summit_sigma *= k;
  smooth.asperities.summit_radius /= k;
  const BearingModel reference(smooth), rough(new_washer());

  // The same state in each new washer's unknowns: the rigid body's clearances in its own
  // σ_ref, film 1's closed by the depths; every other block as it is.
  auto same_state = [&](const BearingModel& m) {
    std::vector<double> u(std::size_t(m.size()));
    for (const UnknownBlock& b : m.layout().blocks()) {
      const UnknownBlock* w = block_named(worn, b.name);
      EXPECT_TRUE(w && w->size == b.size) << b.name;
      if (!w || w->size != b.size) continue;
      std::copy_n(u_worn.begin() + w->offset, b.size, u.begin() + b.offset);
      if (b.effect != BlockEffect::mechanics) continue;
      const double to = worn.clearance_scale() / m.clearance_scale();
      u[std::size_t(b.offset)] = (u_worn[std::size_t(w->offset)] * worn.clearance_scale() + rest_depth + turn_depth) /
                                 m.clearance_scale();
      u[std::size_t(b.offset + 3)] *= to;
    }
    AssemblyTotals totals;
    m.gather_totals(u, totals);
    return totals.film[0];
  };
  AssemblyTotals worn_totals;
  worn.gather_totals(u_worn, worn_totals);
  const FilmTotals& a = worn_totals.film[0];
  const FilmTotals b = same_state(reference), c = same_state(rough);
  auto sum = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); };
  ASSERT_GT(b.contact_force, 1e-3 * b.fluid_force);  // the summits carry a share
  for (auto [name, x, y, z] : {std::tuple{"contact force", a.contact_force, b.contact_force, c.contact_force},
                               std::tuple{"friction power", sum(a.contact_power), sum(b.contact_power), sum(c.contact_power)},
                               std::tuple{"viscous heat", a.viscous_heat, b.viscous_heat, c.viscous_heat},
                               std::tuple{"viscous torque", a.viscous_torque, b.viscous_torque, c.viscous_torque},
                               std::tuple{"outer flow", a.outer_flow, b.outer_flow, c.outer_flow}}) {
    EXPECT_NEAR(x, y, 1e-12 * std::abs(y)) << name;
    EXPECT_GT(std::abs(z - y), 1e-3 * std::abs(y)) << name << ": the washer's new roughness reads the same";
  }
  for (std::size_t n = 0; n < a.contact_power.size(); ++n)
    EXPECT_NEAR(a.contact_power[n], b.contact_power[n], 1e-12 * sum(b.contact_power)) << n;
}

// The paper's washer over 2000 h at 150 N (configs/studies/life.yaml) on the coarse mesh,
// its sliding faces running in to 0.2 µm or not: run in, the rim that first carries the
// load by its summits gets smoother, so that the oil lifts it sooner and it wears less
// deep; life.csv reports each face's Rq falling from the new face's, never below the
// run-in Rq, and the face's Rq without running-in unchanged.
TEST(RunningIn, ALifeReportsItsFacesRunningInAndWearsLessDeep) {
  auto life = [](bool runs_in) {
    std::vector<std::string> overrides{"mesh.radial_nodes=5", "mesh.circumferential_nodes=24",
                                       "study.failure_load=false"};
    if (runs_in)
      for (const char* face : {"carrier", "washer"})
        overrides.push_back(std::string("surfaces.") + face + ".run_in_rq=0.2 um");
    BearingModel model(load_scene(std::string(TWB_SOURCE_DIR) + "/configs/studies/life.yaml", overrides));
    StudyOutcome out = run_study(model, {});
    EXPECT_FALSE(out.solver_failed) << out.message;
    return std::get<LifeOutcome>(out.own).rows;
  };
  const std::vector<LifeRow> run_in = life(true), kept = life(false);
  ASSERT_FALSE(run_in.empty());
  ASSERT_FALSE(kept.empty());
  EXPECT_EQ(run_in.back().event, "end");
  const double rq_new = 0.515e-6;
  EXPECT_NEAR(run_in.front().rest.rq, rq_new, 1e-14 * rq_new);
  for (std::size_t n = 1; n < run_in.size(); ++n) {
    EXPECT_LT(run_in[n].rest.rq, run_in[n - 1].rest.rq) << n;
    EXPECT_LT(run_in[n].turn.rq, run_in[n - 1].turn.rq) << n;
    EXPECT_GE(run_in[n].rest.rq, 0.2e-6) << n;
    EXPECT_GE(run_in[n].turn.rq, 0.2e-6) << n;
  }
  // (to rounding: the node areas sum to the film's)
  for (const LifeRow& row : kept) {
    EXPECT_NEAR(row.rest.rq, rq_new, 1e-14 * rq_new);
    EXPECT_NEAR(row.turn.rq, rq_new, 1e-14 * rq_new);
  }
  EXPECT_LT(run_in.back().rest.deepest, kept.back().rest.deepest);
  EXPECT_LT(run_in.back().turn.deepest, kept.back().turn.deepest);
}

}  // namespace
}  // namespace twb
