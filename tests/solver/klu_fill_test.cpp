// The 4 rigid-body unknowns couple to every film node: a dense border around a sparse
// matrix. KLU must keep that border cheap; with AMD ordering (what the Newton solver
// selects) the border is ordered last and the factors stay within a small multiple of
// the matrix, while COLAMD (SUNDIALS' default) fills them several times more.
#include <gtest/gtest.h>

#include <klu.h>

#include "../support/table1_scene.h"
#include "model/bearing_model.h"
#include "solver/nested_dissection.h"

namespace twb {
namespace {

struct Fill { long factors; long matrix; };

Fill factor_fill(const BearingModel& m, int ordering) {
  const SparsePattern& p = m.pattern();
  std::vector<double> r(std::size_t(m.size())), jac(std::size_t(p.nnz()));
  m.evaluate(m.cold_start(), r, jac);
  std::vector<long> ap(p.row_start.begin(), p.row_start.end()), ai(p.column.begin(), p.column.end());
  klu_l_common common;
  klu_l_defaults(&common);
  common.ordering = ordering;
  if (ordering == 3) common.user_order = nested_dissection_order;
  klu_l_symbolic* sym = klu_l_analyze(long(m.size()), ap.data(), ai.data(), &common);
  klu_l_numeric* num = klu_l_factor(ap.data(), ai.data(), jac.data(), sym, &common);
  EXPECT_NE(num, nullptr) << "KLU could not factor the cold-start Jacobian";
  const Fill f{num ? long(num->lnz + num->unz) : 0, long(p.nnz())};
  klu_l_free_numeric(&num, &common);
  klu_l_free_symbolic(&sym, &common);
  return f;
}

TEST(KluFill, DenseRigidBodyBorderStaysCheapWithAmd) {
  const BearingModel m(testing::table1_scene(true, true, true, true, 545.0, 500.0));
  const Fill amd = factor_fill(m, 0), colamd = factor_fill(m, 1);
  std::cout << "nnz(A) " << amd.matrix << ", nnz(L+U): AMD " << amd.factors << ", COLAMD " << colamd.factors << "\n";
  // Measured 2.6x on the paper's mesh; a dense border ordered early would fill whole
  // rows and columns of the factors (tens of times nnz(A)).
  EXPECT_LT(amd.factors, 4 * amd.matrix);
  EXPECT_LT(amd.factors, colamd.factors);
}

// Above the paper's mesh the border is no longer the story: AMD's factors of the grid
// itself grow faster than the grid, nested dissection's more slowly (measured on
// 17×132: 0.56 and 0.50 million entries; on 65×528 17.0 and 13.4 million).
TEST(KluFill, NestedDissectionFillsLessThanAmdOnAFineMesh) {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 500.0);
  s.mesh.radial_nodes = 17;
  s.mesh.circumferential_nodes = 132;
  const BearingModel m(s);
  const Fill amd = factor_fill(m, 0), nd = factor_fill(m, 3);
  std::cout << "nnz(A) " << amd.matrix << ", nnz(L+U): AMD " << amd.factors << ", nested dissection " << nd.factors
            << "\n";
  EXPECT_LT(nd.factors, amd.factors);
}

}  // namespace
}  // namespace twb
