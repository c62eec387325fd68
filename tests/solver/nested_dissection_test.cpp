// nested_dissection_order, KLU's ordering above SparseLu::kNestedDissectionAbove
// unknowns: a permutation, with the dense border last, that factors a bordered 2-D
// grid matrix correctly and with less fill than AMD.
#include <gtest/gtest.h>

#include <klu.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <thread>
#include <vector>

#include "solver/nested_dissection.h"
#include "solver/sparse_lu.h"

namespace twb {
namespace {

// A periodic n × n five-point grid (an unsymmetric convection term) bordered by two
// dense rows and columns, like the bearing's rigid body: row-compressed.
struct Bordered {
  SparsePattern pattern;
  std::vector<double> values;
};

Bordered bordered_grid(int n) {
  const int grid = n * n, size = grid + 2;
  Bordered b;
  b.pattern.rows = b.pattern.cols = size;
  b.pattern.row_start.push_back(0);
  auto node = [n](int i, int j) { return ((i + n) % n) * n + (j + n) % n; };
  for (int k = 0; k < size; ++k) {
    std::vector<std::pair<Index, double>> row;
    if (k < grid) {
      const int i = k / n, j = k % n;
      row = {{k, 4.5}, {node(i - 1, j), -1.2}, {node(i + 1, j), -0.8}, {node(i, j - 1), -1.0},
             {node(i, j + 1), -1.0}, {grid, 0.01}, {grid + 1, -0.02}};
    } else {
      for (int c = 0; c < grid; ++c) row.emplace_back(c, 1.0 / grid);
      row.emplace_back(k, 2.0);
    }
    std::sort(row.begin(), row.end());
    for (const auto& [c, v] : row) {
      b.pattern.column.push_back(c);
      b.values.push_back(v);
    }
    b.pattern.row_start.push_back(Index(b.pattern.column.size()));
  }
  return b;
}

// The block's order by nested_dissection_order, empty where it reports a failure (0).
std::vector<long> order_of(const Bordered& b) {
  const long n = b.pattern.rows;
  std::vector<long> ap(b.pattern.row_start.begin(), b.pattern.row_start.end());
  std::vector<long> ai(b.pattern.column.begin(), b.pattern.column.end());
  std::vector<long> perm(std::size_t(n), -1);
  klu_l_common common;
  klu_l_defaults(&common);
  if (nested_dissection_order(n, ap.data(), ai.data(), perm.data(), &common) <= 0) return {};
  return perm;
}

TEST(NestedDissection, OrdersEveryUnknownOnceWithTheDenseBorderLast) {
  const Bordered b = bordered_grid(40);
  const long n = b.pattern.rows;
  const std::vector<long> perm = order_of(b);
  ASSERT_FALSE(perm.empty()) << "nested_dissection_order reported a failure";
  std::vector<long> sorted = perm;
  std::sort(sorted.begin(), sorted.end());
  std::vector<long> all(static_cast<std::size_t>(n));
  std::iota(all.begin(), all.end(), 0L);
  EXPECT_EQ(sorted, all);
  EXPECT_EQ(std::vector<long>(perm.end() - 2, perm.end()), (std::vector<long>{n - 2, n - 1}));
}

TEST(NestedDissection, SparseLuSolvesALargeBorderedGrid) {
  // 80² + 2 unknowns: above the threshold, so SparseLu orders by nested dissection.
  const Bordered b = bordered_grid(80);
  ASSERT_GT(b.pattern.rows, SparseLu::kNestedDissectionAbove);
  SparseLu lu(b.pattern);
  ASSERT_TRUE(lu.factor(b.values));
  std::vector<double> x(std::size_t(b.pattern.rows));
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = std::sin(0.1 * double(k));
  const std::vector<double> rhs = x;
  lu.solve(x);
  // The backward error ‖A x − b‖∞ / (‖A‖∞ ‖x‖∞): LU with partial pivoting on these
  // diagonally dominant rows has no pivot growth, so it stays within Higham's γ_k = k·u
  // with k the longest inner product, here a dense border row of n terms (u = 1.1e-16;
  // measured 3.8e-14 against the bound 7.1e-13). A wrong permutation or factor gives
  // errors of order 1.
  double worst = 0.0, norm_a = 0.0, norm_x = 0.0;
  for (Index r = 0; r < b.pattern.rows; ++r) {
    double sum = -rhs[std::size_t(r)], row_sum = 0.0;
    for (Index e = b.pattern.row_start[std::size_t(r)]; e < b.pattern.row_start[std::size_t(r) + 1]; ++e) {
      sum += b.values[std::size_t(e)] * x[std::size_t(b.pattern.column[std::size_t(e)])];
      row_sum += std::abs(b.values[std::size_t(e)]);
    }
    worst = std::max(worst, std::abs(sum));
    norm_a = std::max(norm_a, row_sum);
    norm_x = std::max(norm_x, std::abs(x[std::size_t(r)]));
  }
  std::cout << "backward error " << worst / (norm_a * norm_x) << "\n";
  EXPECT_LT(worst / (norm_a * norm_x), double(b.pattern.rows) * 1.1e-16);
}

// METIS draws on the process's rand() (nested_dissection.cpp, metis_lock): two orders
// found at once on two threads must be the orders each finds alone, or a study's
// results depend on its thread count. The orders kept for reuse are filled first with
// small grids, so that every order below is found afresh by METIS; 40 rounds on two
// threads overlap their METIS calls many times (each takes about a millisecond).
TEST(NestedDissection, TwoThreadsFindTheOrdersOneFinds) {
  for (int n = 3; n < 3 + 16; ++n) ASSERT_FALSE(order_of(bordered_grid(n)).empty());
  const Bordered a = bordered_grid(30), b = bordered_grid(31);
  const std::vector<long> alone_a = order_of(a), alone_b = order_of(b);
  ASSERT_FALSE(alone_a.empty());
  ASSERT_FALSE(alone_b.empty());
  int differ_a = 0, differ_b = 0;
  std::thread first([&] {
    for (int k = 0; k < 40; ++k) differ_a += order_of(a) != alone_a;
  });
  std::thread second([&] {
    for (int k = 0; k < 40; ++k) differ_b += order_of(b) != alone_b;
  });
  first.join();
  second.join();
  EXPECT_EQ(differ_a, 0);
  EXPECT_EQ(differ_b, 0);
}

}  // namespace
}  // namespace twb
