// A SteadySystem's exact ∂F/∂u and ∂F/∂λ against central differences of its residual.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "system/steady_system.h"

namespace twb::testing {

// Central differences at ε = 1e-6 on smooth O(1)–O(e^u) terms: truncation ε²·|F'''|
// ≈ 1e-12·e^u, rounding 1e-16·|F|/ε ≈ 1e-10·max|F|; `relative` = 1e-6 holds with margin.
inline void expect_derivatives_match(SteadySystem& s, const std::vector<double>& u, double relative = 1e-6) {
  const auto n = std::size_t(s.size());
  const SparsePattern& p = s.pattern();
  std::vector<double> r(n), jac(std::size_t(p.nnz())), rp(n), rm(n), dl(n);
  s.evaluate(u, r, jac);
  const double eps = 1e-6;
  for (std::size_t c = 0; c < n; ++c) {
    std::vector<double> up = u, um = u;
    up[c] += eps;
    um[c] -= eps;
    s.evaluate(up, rp, {});
    s.evaluate(um, rm, {});
    for (std::size_t row = 0; row < n; ++row) {
      const double fd = (rp[row] - rm[row]) / (2 * eps);
      const Index at = p.find(Index(row), Index(c));
      const double exact = at >= 0 ? jac[std::size_t(at)] : 0.0;
      EXPECT_NEAR(exact, fd, relative * std::max(1.0, std::abs(fd))) << row << "," << c;
    }
  }
  s.parameter_derivative(u, dl);
  const double l = s.parameter(), el = 1e-6 * std::max(1.0, std::abs(l));
  s.set_parameter(l + el);
  s.evaluate(u, rp, {});
  s.set_parameter(l - el);
  s.evaluate(u, rm, {});
  s.set_parameter(l);
  for (std::size_t row = 0; row < n; ++row)
    EXPECT_NEAR(dl[row], (rp[row] - rm[row]) / (2 * el), relative * std::max(1.0, std::abs(dl[row])));
}

}  // namespace twb::testing
