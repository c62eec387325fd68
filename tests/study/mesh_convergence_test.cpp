// A failure load to a requested accuracy (study/mesh_convergence.h): the estimate from a
// mesh sequence on manufactured values Q(h) = Q* + C·h^p (+ a higher-order term), whose
// mesh-converged value Q* is known, and the sequence's stopping rule.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../src/study/accuracy/mesh_convergence.h"
#include "../support/table1_scene.h"

namespace twb {
namespace {

// Q on the scene's mesh (h = 1) and on n − 1 meshes each refined by two.
std::vector<double> manufactured(double exact, double c, double p, int n, double d = 0.0, double q = 0.0) {
  std::vector<double> values;
  for (int k = 0; k < n; ++k) {
    const double h = std::pow(0.5, k);
    values.push_back(exact + c * std::pow(h, p) + d * std::pow(h, q));
  }
  return values;
}

// An exact power law of order 1.5 (below the formal 2, as W_d's coarse meshes show): the
// observed order is 1.5 and the extrapolation Q* itself, to rounding (the values are
// O(200) and the differences O(10): a few ulps of 200 relative to the change).
TEST(MeshConvergence, ThreeMeshesRecoverAnExactPowerLawOfAnyOrder) {
  const auto values = manufactured(202.62, -40.0, 1.5, 3);
  const MeshConvergence e = mesh_converged(values);
  ASSERT_TRUE(e.order.has_value());
  EXPECT_NEAR(*e.order, 1.5, 1e-12);
  EXPECT_NEAR(e.value, 202.62, 1e-11);
  // The bar is Roache's with F_s = 1.25 on the last step's extrapolation.
  const double step = values[2] - values[1];
  EXPECT_NEAR(e.error, 1.25 * std::abs(step) / (std::pow(2.0, 1.5) - 1.0), 1e-12);
}

// With a higher-order term (h^1.5 led by h^2.5, the data's mix of orders), the bar of three
// meshes covers the true error, and is narrower than the two finest meshes' bar alone
// (|step|, which no third mesh confirms): the third mesh buys a tighter honest bar.
TEST(MeshConvergence, TheBarCoversTheTrueErrorAndNarrowsWithTheThirdMesh) {
  // The higher-order term up to half the leading one on the scene's mesh: observed orders
  // 1.2 to 1.8, the range W_d shows from coarse to fine meshes.
  for (const double d : {-20.0, -10.0, -5.0, 5.0, 10.0}) {
    const auto values = manufactured(202.62, -40.0, 1.5, 3, d, 2.5);
    const MeshConvergence e = mesh_converged(values);
    EXPECT_LE(std::abs(e.value - 202.62), e.error) << "d = " << d;
    const MeshConvergence two = mesh_converged(std::vector<double>{values[1], values[2]});
    EXPECT_LE(std::abs(two.value - 202.62), two.error) << "d = " << d;
    EXPECT_LT(e.error, two.error) << "d = " << d;
  }
}

// The value the next mesh should give, where its solve starts (next_mesh_value): on an
// exact power law the law's own next value, from two meshes where its order is the
// formal two, from three whatever its order (the observed one); one value is its own.
TEST(MeshConvergence, TheNextMeshsValueContinuesThePowerLaw) {
  const auto second_order = manufactured(202.62, -40.0, 2.0, 3);
  EXPECT_NEAR(next_mesh_value(std::vector<double>{second_order[0], second_order[1]}), second_order[2], 1e-11);
  const auto lower_order = manufactured(202.62, -40.0, 1.5, 4);
  EXPECT_NEAR(next_mesh_value(std::vector<double>(lower_order.begin(), lower_order.begin() + 3)), lower_order[3],
              1e-11);
  EXPECT_EQ(next_mesh_value(std::vector<double>{188.38}), 188.38);
}

// An observed order above the formal one is capped at two: a chance of the data must not
// shrink the bar; the extrapolation with order two then still lies within the bar.
TEST(MeshConvergence, AnOrderAboveTheFormalIsCappedAtTwo) {
  const auto values = manufactured(100.0, 16.0, 3.0, 3);
  const MeshConvergence e = mesh_converged(values);
  ASSERT_TRUE(e.order.has_value());
  EXPECT_NEAR(*e.order, 3.0, 1e-12);
  const double step = values[2] - values[1];
  EXPECT_NEAR(e.value, values[2] + step / 3.0, 1e-12);
  EXPECT_LE(std::abs(e.value - 100.0), e.error);
}

// Two meshes confirm no order: the formal order's extrapolation with Roache's two-grid
// factor 3, a bar of the whole step.
TEST(MeshConvergence, TwoMeshesGiveTheStepAsTheBar) {
  const MeshConvergence e = mesh_converged(std::vector<double>{188.38, 198.58});
  EXPECT_FALSE(e.order.has_value());
  EXPECT_NEAR(e.value, 198.58 + 10.2 / 3.0, 1e-12);
  EXPECT_NEAR(e.error, 10.2, 1e-12);
}

// Oscillating or growing steps show no asymptotic range: the finest value, within the
// larger step; only the last three meshes count.
TEST(MeshConvergence, OscillatingOrGrowingStepsGiveTheFinestValueAndTheLargerStep) {
  const MeshConvergence oscillating = mesh_converged(std::vector<double>{300.0, 290.0, 296.0});
  EXPECT_FALSE(oscillating.order.has_value());
  EXPECT_EQ(oscillating.value, 296.0);
  EXPECT_EQ(oscillating.error, 10.0);
  const MeshConvergence growing = mesh_converged(std::vector<double>{300.0, 298.0, 290.0});
  EXPECT_FALSE(growing.order.has_value());
  EXPECT_EQ(growing.error, 8.0);
  // A fourth mesh that settles: the last three show order 2 again.
  const MeshConvergence settled = mesh_converged(std::vector<double>{250.0, 300.0, 296.0, 295.0});
  ASSERT_TRUE(settled.order.has_value());
  EXPECT_NEAR(*settled.order, 2.0, 1e-12);
}

TEST(MeshConvergence, WithinToleranceIsRelativeToTheValue) {
  EXPECT_TRUE(within_tolerance({200.0, 2.0, std::nullopt}, 0.01));
  EXPECT_FALSE(within_tolerance({200.0, 2.01, std::nullopt}, 0.01));
  EXPECT_TRUE(within_tolerance({-200.0, 2.0, std::nullopt}, 0.01));
}

// The sequence asks for meshes while the bar is outside the tolerance, up to
// mesh.max_refinements, and says why it ended short.
TEST(MeshSequenceToTolerance, RefinesUntilTheToleranceOrTheLimit) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 100.0);
  testing::use_coarse_mesh(s);  // 5 x 24
  s.mesh.max_refinements = 2;
  const auto values = manufactured(200.0, -20.0, 2.0, 3);  // 180, 195, 198.75
  MeshSequence sequence(s, values[0]);
  ASSERT_NE(sequence.next_mesh(), nullptr);
  EXPECT_EQ(sequence.next_mesh()->mesh.radial_nodes, 9);
  EXPECT_EQ(sequence.next_mesh()->mesh.circumferential_nodes, 48);
  EXPECT_TRUE(sequence.wants_more(0.01));
  sequence.add(values[1]);
  // Two meshes: the bar is the step (15 N), 7.5 % of the value (200 N).
  EXPECT_TRUE(sequence.wants_more(0.07));
  EXPECT_FALSE(sequence.wants_more(0.08));
  ASSERT_NE(sequence.next_mesh(), nullptr);
  EXPECT_EQ(sequence.next_mesh()->mesh.radial_nodes, 17);
  sequence.add(values[2]);
  EXPECT_EQ(sequence.solved_meshes(), "5x24 9x48 17x96");
  // An exact order-2 law: the bar is 1.25·|step|/3 = 1.5625 N, 0.78 % of 200 N.
  EXPECT_FALSE(sequence.wants_more(0.008));
  EXPECT_TRUE(sequence.wants_more(0.0078));
  EXPECT_EQ(sequence.next_mesh(), nullptr);  // the limit: two refinements
  EXPECT_NE(sequence.why_unmet(0.005).find("mesh.max_refinements: 2"), std::string::npos)
      << sequence.why_unmet(0.005);
  sequence.stop("Newton failed");
  EXPECT_FALSE(sequence.wants_more(0.005));
  EXPECT_NE(sequence.why_unmet(0.005).find("Newton failed"), std::string::npos);
}

}  // namespace
}  // namespace twb
