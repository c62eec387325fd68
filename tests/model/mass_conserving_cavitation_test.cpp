// Mass-conserving (JFO / Elrod–Adams) cavitation, docs/physics.md section 12: what a converged
// state promises, and the answer it gives for the washer's full annulus.
//
// The annulus is periodic in θ and flooded only at its two radii, and the sliding is
// circumferential: oil can enter the film only by Poiseuille flow from an edge, which
// needs an interior pressure below the edge's. With the cavity at ambient (p ≥ 0) none
// is, while any pressure above ambient pushes oil out through the edges; so a steady
// film loses what it carries until no pressure is left: the analytic steady state is
// p ≡ 0, the load on contact alone. A cavity below ambient draws oil in from the edges
// and the film carries load again. The Reynolds condition, by contrast, creates oil
// wherever the film ruptures (w > 0 there) — the mass the JFO balance conserves.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "../support/converged_balances.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

Scene washer(CavitationModel cavitation, double cavity_pressure, bool thermal) {
  Scene s = testing::table1_scene(true, true, true, thermal, 545.0, 150.0);
  testing::use_coarse_mesh(s);
  s.effects.cavitation = cavitation;
  s.effects.cavity_pressure = cavity_pressure;
  return s;
}

std::vector<double> solved(BearingModel& m) {
  SteadySolver solver(m, {});
  std::vector<double> u;
  const SteadyReport rep = solver.solve_cold(u);
  EXPECT_TRUE(rep.converged) << rep.message;
  return u;
}

const UnknownBlock& block(const BearingModel& m, const std::string& name) {
  for (const UnknownBlock& b : m.layout().blocks())
    if (b.name == name) return b;
  throw std::logic_error("no block " + name);
}

TEST(MassConservingCavitation, AddsTheFilmContentAtThePressureNodes) {
  const BearingModel reynolds(washer(CavitationModel::reynolds, 0.0, false));
  const BearingModel jfo(washer(CavitationModel::jfo, 0.0, false));
  EXPECT_EQ(jfo.size(), reynolds.size() + block(jfo, "film 1 pressure").size);
  EXPECT_EQ(block(jfo, "film 1 film content").size, block(jfo, "film 1 pressure").size);
}

TEST(MassConservingCavitation, EveryControlVolumeConservesMassToTheTolerance) {
  for (const bool thermal : {false, true}) {
    BearingModel m(washer(CavitationModel::jfo, -0.3e5, thermal));
    const std::vector<double> u = solved(m);
    std::vector<double> r(u.size());
    m.evaluate(u, r, {});
    // The content rows are the control volumes' flow balances over their reference
    // flux: the solver's tolerance (1e-10) bounds each, rupture and reformation included.
    const UnknownBlock& content = block(m, "film 1 film content");
    double worst = 0, least = 1, most = 0;
    for (Index k = content.offset; k < content.offset + content.size; ++k) {
      worst = std::max(worst, std::abs(r[k]));
      least = std::min(least, u[k]);
      most = std::max(most, u[k]);
    }
    EXPECT_LE(worst, 1e-10);
    // The film ruptures (some content below 1) and is full elsewhere (content 1 where p > p_cav).
    EXPECT_LT(least, 0.9);
    EXPECT_NEAR(most, 1.0, 1e-9);
    const BearingState s = m.describe(u);
    testing::expect_balanced(s);
    // A cavity below ambient feeds the film, which carries load (0.43 of it isothermal
    // on this mesh), where the ambient cavity's carries none (the last test).
    EXPECT_GT(s.fluid_share, 0.1);
  }
}

TEST(MassConservingCavitation, ReynoldsConditionCreatesOilWhereTheFilmRuptures) {
  BearingModel m(washer(CavitationModel::reynolds, 0.0, false));
  const std::vector<double> u = solved(m);
  // The same state's pressure rows as plain flow balances ŵ (net outflow over its
  // reference): where the film ruptures (p = 0) more oil leaves a control volume than
  // enters — oil the JFO balance would not let exist.
  m.set_flow_balance_rows(true);
  std::vector<double> w(u.size());
  m.evaluate(u, w, {});
  const UnknownBlock& pressure = block(m, "film 1 pressure");
  double created = 0;
  for (Index k = pressure.offset; k < pressure.offset + pressure.size; ++k)
    if (u[k] <= 1e-12) created = std::max(created, w[k]);
  EXPECT_GT(created, 1e-3);  // seven orders above the tolerance: not rounding
}

TEST(MassConservingCavitation, WasherFilmDrainsWithTheCavityAtAmbient) {
  BearingModel m(washer(CavitationModel::jfo, 0.0, false));
  const std::vector<double> u = solved(m);
  const BearingState s = m.describe(u);
  // p ≡ 0 (to the tolerance: p̂ ≤ 1e-10 of p_ref = load / film area): no lift, the
  // load on contact alone.
  EXPECT_LT(std::abs(s.fluid_share), 1e-8);
  EXPECT_NEAR(s.contact_share, 1.0, 1e-8);
  const UnknownBlock& content = block(m, "film 1 film content");
  for (Index k = content.offset; k < content.offset + content.size; ++k) {
    EXPECT_GT(u[k], 0.0);
    EXPECT_LE(u[k], 1.0 + 1e-10);
  }
}

}  // namespace
}  // namespace twb
