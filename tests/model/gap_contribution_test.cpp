// A part of the films' gap registered from outside the model (model/gap_contribution.h;
// the worked example support/prescribed_wear.h): the model sums it with thermal
// deformation's at every node, every kernel reads it (a uniform worn depth is a shift of
// the clearance and nothing else), and its unknowns move to another mesh with the model.
// Its slopes in every kernel are jacobian_test's "prescribed_wear" cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../support/prescribed_wear.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"

namespace twb {
namespace {

Scene heated_washer() {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 300.0);
  testing::use_coarse_mesh(s);
  return s;
}

double uniform_depth(const Scene& s) { return 0.4 * s.asperities.summit_sigma; }

std::unique_ptr<BearingModel> worn(const Scene& s, testing::PrescribedWear::Depth depth) {
  return std::make_unique<BearingModel>(s, std::vector{testing::PrescribedWear::maker(std::move(depth))});
}

const UnknownBlock* block_named(const BearingModel& m, const std::string& name) {
  for (const UnknownBlock& b : m.layout().blocks())
    if (b.name == name) return &b;
  return nullptr;
}

double largest(const std::vector<double>& v) {
  double most = 0.0;
  for (double x : v) most = std::max(most, std::abs(x));
  return most;
}

// Film 1's gap opened by d everywhere is the same gap with the washer d lower, its
// clearance c1 = z_w less by d: h1 = (c1 − d) + … + d; film 2's own clearance c2, the
// other unknown, is untouched. So the solved state of the unworn washer, moved so and with
// the worn depth's and the contact force's unknowns filled in, is a root of the worn
// washer's equations: its residual is the
// unworn one's (within the solver's 1e-10) up to rounding. The rounding is that of rows
// summing terms up to ~1e4 of their scale (jacobian_test's note), ~1e-12; the bound is
// 1e-9, where a kernel that left the part out would be off by about d/h, above 0.1.
TEST(GapContribution, AUniformWornDepthIsAShiftOfTheClearance) {
  const Scene s = heated_washer();
  BearingModel unworn(s);
  std::vector<double> u;
  ASSERT_TRUE(SteadySolver(unworn, {}).solve_cold(u).converged);
  const double d = uniform_depth(s);
  const std::unique_ptr<BearingModel> model = worn(s, [d](double, double) { return d; });
  ASSERT_TRUE(model->gap_shaped());
  ASSERT_EQ(unworn.contact_force_unknown(), -1);
  ASSERT_GE(model->contact_force_unknown(), 0) << "a shaped gap with the empirical law";

  std::vector<double> v(std::size_t(model->size()), 0.0);
  for (const UnknownBlock& b : unworn.layout().blocks()) {
    const UnknownBlock* mine = block_named(*model, b.name);
    ASSERT_NE(mine, nullptr) << b.name;
    std::copy(u.begin() + b.offset, u.begin() + b.offset + b.size, v.begin() + mine->offset);
  }
  const UnknownBlock* depth = block_named(*model, "film 1 worn depth");
  ASSERT_NE(depth, nullptr);
  for (Index k = depth->offset; k < depth->offset + depth->size; ++k) v[std::size_t(k)] = d / model->clearance_scale();
  const Index rigid = model->films()[0].rigid_offset;
  std::vector<double> r(v.size());
  // Unmoved, the worn film is off its balance: the check can fail.
  std::vector<double> unmoved = v;
  model->evaluate(unmoved, r, {});
  const double off_balance = largest(r);
  EXPECT_GT(off_balance, 1e-3);
  v[std::size_t(rigid)] -= d / model->clearance_scale();  // ĉ1
  // The contact force's row reads F̂c − F_c/F_ref: at F̂c = 0 it is −F_c/F_ref.
  const Index force = model->contact_force_unknown();
  model->evaluate(v, r, {});
  v[std::size_t(force)] = -r[std::size_t(force)];
  model->evaluate(v, r, {});
  EXPECT_GT(v[std::size_t(force)], 0.0) << "contact carries part of the load at 300 N";
  EXPECT_LE(largest(r), 1e-9) << "unmoved: " << off_balance;
  // What the state reports of the gap reads the part too: the least gap and every node's
  // gap are the unworn ones (to rounding of the clearance, a few ulps of a micrometre).
  for (std::size_t f = 0; f < unworn.films().size(); ++f) {
    const double least = unworn.least_gap(u, unworn.films()[f]);
    EXPECT_NEAR(model->least_gap(v, model->films()[f]), least, 1e-14 * std::abs(least)) << "film " << f + 1;
  }
  const std::vector<FilmFields> before = unworn.fields(u), after = model->fields(v);
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t f = 0; f < before.size(); ++f)
    for (std::size_t n = 0; n < before[f].gap.size(); ++n)
      EXPECT_NEAR(after[f].gap[n], before[f].gap[n], 1e-14 * std::abs(before[f].gap[n])) << "film " << f + 1;
}

// Each node's shape form is the sum of the parts' in their order: thermal deformation's
// (registered by the scene's effect) and then the worn depth's, σ_ref per unit of d̂ on
// film 1 and nothing on film 2. The unknowns before the worn block are numbered alike.
TEST(GapContribution, ThePartsFormsAddAtEveryNode) {
  Scene s = heated_washer();
  s.effects.thermal_deformation = true;
  const BearingModel deformed(s);
  const std::unique_ptr<BearingModel> both = worn(s, [](double r, double) { return 1e-7 * r / 0.01; });
  ASSERT_EQ(both->gap_parts().size(), 2u);
  EXPECT_EQ(both->gap_parts()[0]->name(), "thermal deformation");
  const UnknownBlock* depth = block_named(*both, "film 1 worn depth");
  ASSERT_NE(depth, nullptr);
  for (const Film& film : both->films()) {
    const Film& same = deformed.films()[std::size_t(film.number - 1)];
    for (int n = 0; n < film.mesh.node_count(); ++n) {
      const auto& mine = both->shape_form(film, n).terms;
      const auto& thermal = deformed.shape_form(same, n).terms;
      ASSERT_EQ(mine.size(), thermal.size() + (film.number == 1 ? 1u : 0u)) << "film " << film.number << " node " << n;
      for (std::size_t t = 0; t < thermal.size(); ++t) {
        EXPECT_EQ(mine[t].first, thermal[t].first);
        EXPECT_EQ(mine[t].second, thermal[t].second);
      }
      if (film.number == 1) {
        EXPECT_EQ(mine.back().first, depth->offset + n);
        EXPECT_EQ(mine.back().second, both->clearance_scale());
      }
    }
  }
}

// The model on another mesh registers the part again (on_mesh passes its effects on), and
// a state carried there gets the part's unknowns from the part's own effect.
TEST(GapContribution, ItsUnknownsMoveToAnotherMesh) {
  const Scene s = heated_washer();
  const double d = uniform_depth(s);
  const std::unique_ptr<BearingModel> coarse = worn(s, [d](double r, double) { return d * r / 0.01; });
  const std::unique_ptr<BearingModel> fine = coarse->on_mesh(9, 48);
  ASSERT_TRUE(fine->gap_shaped());
  const UnknownBlock* depth = block_named(*fine, "film 1 worn depth");
  ASSERT_NE(depth, nullptr);
  EXPECT_EQ(depth->size, 9 * 48);
  const std::vector<double> carried = fine->interpolated_from(*coarse, coarse->cold_start());
  const FilmMesh& m = fine->films()[0].mesh;
  for (int n = 0; n < m.node_count(); ++n)
    EXPECT_DOUBLE_EQ(carried[std::size_t(depth->offset + n)] * fine->clearance_scale(),
                     d * m.radius(n / m.circumferential_nodes()) / 0.01);
}

}  // namespace
}  // namespace twb

namespace twb {
namespace {

// Thermal deformation's own unknowns move to another mesh by its effect's carry_from (the
// dishing curvature) and the model's (the contact force), in physical units: the same
// scene on both meshes has the same scales, so they arrive unchanged.
TEST(GapContribution, ThermalDeformationsUnknownsMoveToAnotherMesh) {
  Scene s = heated_washer();
  s.effects.thermal_deformation = true;
  BearingModel coarse(s);
  std::vector<double> u;
  ASSERT_TRUE(SteadySolver(coarse, {}).solve_cold(u).converged);
  ASSERT_GE(coarse.contact_force_unknown(), 0);
  ASSERT_NE(coarse.dishing_curvature(u), 0.0);
  const std::unique_ptr<BearingModel> fine = coarse.on_mesh(9, 48);
  const std::vector<double> v = fine->interpolated_from(coarse, u);
  EXPECT_DOUBLE_EQ(fine->dishing_curvature(v), coarse.dishing_curvature(u));
  EXPECT_DOUBLE_EQ(v[std::size_t(fine->contact_force_unknown())] * fine->contact_force_scale(),
                   u[std::size_t(coarse.contact_force_unknown())] * coarse.contact_force_scale());
}

}  // namespace
}  // namespace twb
