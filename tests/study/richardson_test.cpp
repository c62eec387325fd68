// W_d's error bar (study/richardson.h) on three meshes of the paper's bearing: the
// scene's coarse mesh, refined by two, and refined by two again. Coarse meshes keep it
// fast; the folds need no transients.
#include <gtest/gtest.h>

#include <cmath>

#include "../../src/study/richardson.h"
#include "../support/table1_scene.h"

namespace twb {
namespace {

DistressSearchSettings fold_range() {
  DistressSearchSettings s;
  s.load_start = 100.0;
  s.load_end = 600.0;
  return s;
}

double fold_on(const Scene& scene) {
  BearingModel model(scene);
  DistressSearchSettings s = fold_range();
  s.fold_only = true;
  const DistressSearch found = search_distress(model, s, {});
  if (!found.row.fold_load) throw std::runtime_error("no fold: " + found.row.method);
  return *found.row.fold_load;
}

TEST(RichardsonEstimate, RefinesBothDirectionsByTwo) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 100.0);
  testing::use_coarse_mesh(s);
  const Scene fine = refined_mesh(s);
  EXPECT_EQ(fine.mesh.radial_nodes - 1, 2 * (s.mesh.radial_nodes - 1));
  EXPECT_EQ(fine.mesh.circumferential_nodes, 2 * s.mesh.circumferential_nodes);
}

// The observed order of W_d over the three meshes lies where the error bar's argument
// needs it (p >= 1.25; formal order 2), and the bar of the coarse pair covers the finer
// pair's extrapolation, the best estimate of the mesh-converged W_d the test can afford.
TEST(RichardsonEstimate, ErrorBarCoversTheFinerExtrapolation) {
  Scene coarse = testing::table1_scene(true, true, true, true, 545.0, 100.0);
  testing::use_coarse_mesh(coarse);
  const Scene middle = refined_mesh(coarse), finest = refined_mesh(middle);
  const double w1 = fold_on(coarse);
  std::string why;
  const auto first = richardson_estimate(coarse, 545.0, w1, fold_range(), why);
  ASSERT_TRUE(first) << why;
  const double w2 = first->fine_fold;
  // The estimate's refined fold is the middle mesh's own (same search, same mesh).
  EXPECT_NEAR(w2, fold_on(middle), 1e-9 * w2);
  const auto second = richardson_estimate(middle, 545.0, w2, fold_range(), why);
  ASSERT_TRUE(second) << why;
  const double w3 = second->fine_fold;

  const double order = std::log2((w2 - w1) / (w3 - w2));
  EXPECT_GE(order, 1.25) << w1 << " " << w2 << " " << w3;
  EXPECT_LE(order, 3.0) << w1 << " " << w2 << " " << w3;
  EXPECT_NEAR(first->extrapolated, w2 + (w2 - w1) / 3.0, 1e-12 * w2);
  EXPECT_LE(std::abs(first->extrapolated - second->extrapolated), first->error)
      << "coarse pair " << first->extrapolated << " ± " << first->error << ", finer pair " << second->extrapolated;
  // The finer pair's bar is the smaller one: the estimate converges.
  EXPECT_LT(second->error, first->error);
}

}  // namespace
}  // namespace twb
