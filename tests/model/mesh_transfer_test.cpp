// BearingModel::interpolated_from, the start of a mesh sequence: bilinear interpolation
// of every field between two meshes of the same scene, in physical units.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/state_difference.h"
#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "study/searches/steady_solver.h"
#include "twb/error_family.h"

namespace twb {
namespace {

Scene on_mesh(Scene s, int nr, int nt) {
  s.mesh.radial_nodes = nr;
  s.mesh.circumferential_nodes = nt;
  return s;
}

TEST(MeshTransfer, OntoTheSameMeshIsTheIdentity) {
  const BearingModel m(on_mesh(testing::table1_scene(true, true, true, true, 545.0, 150.0), 5, 24));
  std::vector<double> u;
  ASSERT_TRUE(SteadySolver(const_cast<BearingModel&>(m), {}).solve_cold(u).converged);
  // Every target node is a source node: the interpolation weights are exactly 0 and 1.
  EXPECT_EQ(m.interpolated_from(m, u), u);
}

TEST(MeshTransfer, KeepsNestedNodesAndPhysicalValuesAcrossScales) {
  const Scene base = testing::table1_scene(true, true, true, true, 545.0, 150.0);
  BearingModel coarse(on_mesh(base, 5, 24));
  std::vector<double> u;
  ASSERT_TRUE(SteadySolver(coarse, {}).solve_cold(u).converged);
  // The fine model is built for another load, so its pressure scale differs: values
  // must go through pascals, not through the scaled unknowns.
  Scene fine_scene = on_mesh(base, 9, 48);
  fine_scene.operating.load = 300.0;
  const BearingModel fine(fine_scene);
  ASSERT_NE(fine.pressure_scale(), coarse.pressure_scale());
  const std::vector<double> v = fine.interpolated_from(coarse, u);

  const Film& fc = coarse.films()[0];
  const Film& ff = fine.films()[0];
  // Node (i, j) of the coarse mesh is node (2i, 2j) of the fine one.
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 24; ++j) {
      EXPECT_NEAR(fine.pressure_at(v, ff, 2 * i, 2 * j), coarse.pressure_at(u, fc, i, j),
                  1e-12 * coarse.pressure_scale());
      EXPECT_DOUBLE_EQ(v[std::size_t(ff.temperature_offset + 2 * i * 48 + 2 * j)],
                       u[std::size_t(fc.temperature_offset + i * 24 + j)]);
    }
  // A node between two coarse ones (a radial midpoint, periodic wrap in θ) takes
  // their mean.
  const double between = 0.25 * (coarse.pressure_at(u, fc, 1, 23) + coarse.pressure_at(u, fc, 1, 0) +
                                 coarse.pressure_at(u, fc, 2, 23) + coarse.pressure_at(u, fc, 2, 0));
  EXPECT_NEAR(fine.pressure_at(v, ff, 3, 47), between, 1e-12 * coarse.pressure_scale());
  const RigidPosition pc = coarse.position(u), pf = fine.position(v);
  EXPECT_DOUBLE_EQ(pf.c1, pc.c1);
  EXPECT_DOUBLE_EQ(pf.gamma_x, pc.gamma_x);
  EXPECT_DOUBLE_EQ(pf.c2, pc.c2);
}

TEST(MeshTransfer, RefusesAnotherSetOfUnknowns) {
  const BearingModel thermal(on_mesh(testing::table1_scene(true, true, true, true), 5, 24));
  const BearingModel isothermal(on_mesh(testing::table1_scene(true, true, true, false), 5, 24));
  const std::vector<double> u = isothermal.cold_start();
  EXPECT_THROW((void)thermal.interpolated_from(isothermal, u), twb::InternalError);
}

// The cold start on a mesh above SteadySolver::kSequenceAbove nodes goes through the
// mesh with every other node line; it must end on the state the cold start on the
// mesh itself reaches.
TEST(MeshSequence, ReachesTheStateOfTheMeshsOwnColdStart) {
  BearingModel m(on_mesh(testing::table1_scene(true, true, true, true, 545.0, 150.0), 17, 132));
  ASSERT_GT(m.films()[0].mesh.node_count(), SteadySolver::kSequenceAbove);
  SteadySolver sequenced(m, {});
  std::vector<double> a;
  const SteadyReport rep = sequenced.solve_cold(a);
  ASSERT_TRUE(rep.converged) << rep.message;
  EXPECT_EQ(rep.strategy, "mesh sequence");

  SteadySolver direct(m, {});
  direct.set_mesh_sequence(false);
  std::vector<double> b;
  const SteadyReport rep_b = direct.solve_cold(b);
  ASSERT_TRUE(rep_b.converged) << rep_b.message;
  EXPECT_EQ(rep_b.strategy, "pseudo-transient");
  // Both meet the residual tolerance 1e-10; as in ColdStart, states within 1e-9 of each
  // other are the same state.
  EXPECT_LT(testing::relative_difference(a, b), 1e-9);
}

// A fine mesh whose half would not be a legal one (fewer than 5 radial nodes: no
// interior pressure worth the name) is not sequenced: its own cold start solves it.
TEST(MeshSequence, StopsAboveTheCoarsestLegalMesh) {
  BearingModel m(on_mesh(testing::table1_scene(true, true, true, true, 545.0, 150.0), 5, 400));
  ASSERT_GT(m.films()[0].mesh.node_count(), SteadySolver::kSequenceAbove);
  std::vector<double> u;
  const SteadyReport rep = SteadySolver(m, {}).solve_cold(u);
  ASSERT_TRUE(rep.converged) << rep.message;
  EXPECT_EQ(rep.strategy, "pseudo-transient");
}

}  // namespace
}  // namespace twb
