// SparseLu::refactor, the rule the Newton solver's and the pseudo-time stepper's
// factorizations share: reuse the last full factorization's pivots while that is safe,
// pivot afresh on a zero pivot or large pivot growth, and always solve correctly.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "solver/sparse_lu.h"

namespace twb {
namespace {

// A full 3×3 pattern, values row by row.
SparsePattern full3() {
  SparsePattern p;
  p.rows = p.cols = 3;
  p.row_start = {0, 3, 6, 9};
  p.column = {0, 1, 2, 0, 1, 2, 0, 1, 2};
  return p;
}

// Solves A x = b by SparseLu::refactor and checks x against Eigen's dense LU.
void expect_solves(SparseLu& lu, const std::vector<double>& a) {
  ASSERT_TRUE(lu.refactor(a));
  const Eigen::Matrix3d dense = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(a.data());
  const Eigen::Vector3d b(1.0, -2.0, 0.5), exact = dense.lu().solve(b);
  std::vector<double> x(b.data(), b.data() + 3);
  lu.solve(x);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(x[std::size_t(k)], exact(k), 1e-12 * exact.cwiseAbs().maxCoeff());
}

TEST(SparseLu, RefactorReusesPivotsOfANearbyMatrix) {
  const SparsePattern p = full3();
  SparseLu lu(p);
  expect_solves(lu, {4, 1, 0.5, 1, 5, 1, 0.5, 1, 6});
  expect_solves(lu, {4.2, 1.1, 0.4, 0.9, 5.3, 1, 0.6, 1, 5.8});
  EXPECT_EQ(lu.counts().analyses, 1);
  EXPECT_EQ(lu.counts().factorizations, 1);
  EXPECT_EQ(lu.counts().refactorizations, 1);
}

TEST(SparseLu, RefactorPivotsAfreshOnAZeroPivot) {
  const SparsePattern p = full3();
  SparseLu lu(p);
  expect_solves(lu, {4, 1, 0.5, 1, 5, 1, 0.5, 1, 6});  // pivots on the diagonal
  expect_solves(lu, {0, 1, 0, 1, 0, 0, 0, 0, 1});      // a permutation: zero diagonal
  EXPECT_EQ(lu.counts().factorizations, 2);
  EXPECT_EQ(lu.counts().refactorizations, 1);
}

TEST(SparseLu, RefactorPivotsAfreshOnLargePivotGrowth) {
  const SparsePattern p = full3();
  SparseLu lu(p);
  expect_solves(lu, {4, 1, 0.5, 1, 5, 1, 0.5, 1, 6});
  // The old pivot (0, 0) is now 1e-9 of its column: U's entries grow ~1e9-fold.
  expect_solves(lu, {1e-9, 1, 0.5, 1, 5, 1, 0.5, 1, 6});
  EXPECT_EQ(lu.counts().factorizations, 2);
}

TEST(SparseLu, RefactorReportsASingularMatrix) {
  const SparsePattern p = full3();
  SparseLu lu(p);
  EXPECT_FALSE(lu.refactor(std::vector<double>{1, 2, 3, 2, 4, 6, 1, 1, 1}));
  EXPECT_FALSE(lu.factored());
  expect_solves(lu, {4, 1, 0.5, 1, 5, 1, 0.5, 1, 6});
}

}  // namespace
}  // namespace twb
