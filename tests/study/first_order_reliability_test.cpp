// FORM, inverse FORM and importance sampling against limit states whose failure
// probability is known in closed form (docs/physics.md section 17).
#include <cmath>
#include <numeric>

#include <boost/math/distributions/normal.hpp>
#include <gtest/gtest.h>

#include "scene/input_distribution.h"
#include "study/uncertainty/first_order_reliability.h"
#include "study/uncertainty/importance_sampling.h"
#include "study/uncertainty/input_neighbours.h"

namespace twb {
namespace {

double phi_upper(double beta) { return boost::math::cdf(boost::math::complement(boost::math::normal(), beta)); }

// W_fail = a0 + a·u: linear in standard normal inputs, where FORM is exact:
// β = (a0 − W)/|a|, u* = −β a/|a|.
FailureLoadFunction linear(double a0, std::vector<double> a) {
  return [a0, a](std::span<const double> u, bool gradient, std::string&) -> std::optional<FailureLoadValue> {
    FailureLoadValue v{a0 + std::inner_product(a.begin(), a.end(), u.begin(), 0.0), {}};
    if (gradient) v.gradient = a;
    return v;
  };
}

TEST(FirstOrderReliability, LinearLimitStateInNormalInputsIsExact) {
  const std::vector<double> a{-30.0, 12.0, 4.0};
  const double a0 = 188.0, load = 120.0;
  const DesignPoint p = design_point(linear(a0, a), 3, load);
  ASSERT_TRUE(p.converged) << p.why;
  const double norm = std::sqrt(900.0 + 144.0 + 16.0);
  const double beta = (a0 - load) / norm;
  // One HL-RF step lands on a linear surface exactly: rounding only.
  EXPECT_NEAR(p.beta, beta, 1e-12 * beta);
  EXPECT_NEAR(p.probability, phi_upper(beta), 1e-12 * phi_upper(beta));
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(p.alpha[i], -a[i] / norm, 1e-12);
    EXPECT_NEAR(p.u[i], -beta * a[i] / norm, 1e-10);
  }
  EXPECT_LE(p.iterations, 3);
}

TEST(FirstOrderReliability, OperatingLoadAboveTheMeanFailureLoadGivesANegativeIndex) {
  const DesignPoint p = design_point(linear(100.0, {10.0}), 1, 115.0);
  ASSERT_TRUE(p.converged) << p.why;
  EXPECT_NEAR(p.beta, -1.5, 1e-12);
  EXPECT_NEAR(p.probability, phi_upper(-1.5), 1e-12);
}

// W_fail = x1·x2 of lognormal inputs: ln W_fail is linear in u, so the failure surface
// is a hyperplane in u and FORM is exact although W_fail is not linear: β = (μ1 + μ2 −
// ln W)/√(σ1² + σ2²) with the logarithms' μ, σ. A test of the transform and of the
// iteration on a curved W_fail.
struct Product {
  UncertainInput x1{"a", "1", InputDistribution::lognormal, 200.0, 30.0};
  UncertainInput x2{"b", "1", InputDistribution::lognormal, 1.0, 0.08};
  static double sigma(const UncertainInput& in) { return std::sqrt(std::log1p(std::pow(in.sd / in.mean, 2))); }
  static double mu(const UncertainInput& in) { return std::log(in.mean) - 0.5 * std::pow(sigma(in), 2); }
  FailureLoadFunction h() const {
    return [this](std::span<const double> u, bool gradient, std::string&) -> std::optional<FailureLoadValue> {
      const double a = input_at(x1, u[0]), b = input_at(x2, u[1]);
      FailureLoadValue v{a * b, {}};
      if (gradient) v.gradient = {b * input_slope(x1, u[0]), a * input_slope(x2, u[1])};
      return v;
    };
  }
  double beta(double load) const {
    return (mu(x1) + mu(x2) - std::log(load)) / std::hypot(sigma(x1), sigma(x2));
  }
};

TEST(FirstOrderReliability, LognormalProductConvergesToTheExactIndex) {
  const Product s;
  const double load = 120.0;
  const DesignPoint p = design_point(s.h(), 2, load);
  ASSERT_TRUE(p.converged) << p.why;
  // Converged to |g| ≤ 1e-4·W: β within that over |∇g| ≈ W·σ.
  EXPECT_NEAR(p.beta, s.beta(load), 1e-3);
  EXPECT_NEAR(p.load, load, 1e-4 * load);
}

TEST(FirstOrderReliability, InverseFormFindsTheLoadOfAProbability) {
  const Product s;
  for (const double probability : {1e-4, 1e-3, 1e-2, 0.3, 0.7}) {
    const DesignPoint p = inverse_design_point(s.h(), 2, probability);
    ASSERT_TRUE(p.converged) << p.why;
    const double beta = reliability_index(probability);
    const double exact = std::exp(s.mu(s.x1) + s.mu(s.x2) - beta * std::hypot(Product::sigma(s.x1), Product::sigma(s.x2)));
    // The direction converged to 1e-3 of β: the load's error is second order in it.
    EXPECT_NEAR(p.load, exact, 1e-5 * exact) << probability;
    EXPECT_NEAR(s.beta(p.load), beta, 1e-5) << probability;
  }
}

TEST(FirstOrderReliability, UnevaluableMeanInputsAreReported) {
  const FailureLoadFunction h = [](std::span<const double>, bool, std::string& why) -> std::optional<FailureLoadValue> {
    why = "the scene refuses it";
    return std::nullopt;
  };
  const DesignPoint p = design_point(h, 2, 100.0);
  EXPECT_FALSE(p.converged);
  EXPECT_NE(p.why.find("the scene refuses it"), std::string::npos) << p.why;
}

// Importance sampling round the exact design point of a linear limit state: the
// estimate lies within three of its standard errors of Φ(−β) (a 0.3 % chance to miss
// for a seed; the test is deterministic), and it reached the coefficient of variation.
TEST(ImportanceSampling, EstimatesALinearLimitStatesProbability) {
  const std::vector<double> a{-30.0, 12.0};
  const double a0 = 188.0, load = 115.0;
  const DesignPoint p = design_point(linear(a0, a), 2, load);
  ASSERT_TRUE(p.converged);
  const FailureIndicator fails = [&](std::uint64_t, std::span<const double> u) -> std::optional<bool> {
    return a0 + a[0] * u[0] + a[1] * u[1] <= load;
  };
  SamplingSettings settings;
  settings.cov = 0.05;
  const SamplingEstimate e = importance_sampling(fails, p.u, settings);
  EXPECT_TRUE(e.reached);
  EXPECT_LE(e.cov, 0.05);
  EXPECT_NEAR(e.probability, p.probability, 3.0 * e.cov * e.probability);
  // Round the design point about half the samples fail: hundreds, not the 1/P_f of
  // plain sampling.
  EXPECT_LT(e.samples, 2000);
  EXPECT_GT(e.failures, e.samples / 4);
}

TEST(ImportanceSampling, TheEstimateDoesNotDependOnTheThreadCount) {
  const FailureIndicator fails = [](std::uint64_t, std::span<const double> u) -> std::optional<bool> {
    if (u[0] > 3.5) return std::nullopt;  // some unresolved samples too
    return 1.0 - 0.4 * u[0] - 0.2 * u[1] * u[1] <= 0.0;
  };
  const std::vector<double> centre{2.0, 0.5};
  SamplingSettings one;
  one.max_samples = 600;
  one.cov = 1e-6;  // never reached: every sample drawn
  SamplingSettings two = one;
  two.threads = 2;
  const SamplingEstimate a = importance_sampling(fails, centre, one), b = importance_sampling(fails, centre, two);
  EXPECT_EQ(a.samples, 600);
  EXPECT_GT(a.unresolved, 0);
  EXPECT_EQ(a.probability, b.probability);
  EXPECT_EQ(a.cov, b.cov);
  EXPECT_EQ(a.failures, b.failures);
  EXPECT_EQ(a.unresolved, b.unresolved);
}

// Each distribution's transform against Boost's own quantiles, its slope against a
// difference, and u = 0 at the median.
TEST(InputDistribution, TransformsMatchTheDistributionsQuantiles) {
  const boost::math::normal standard;
  const UncertainInput uniform{"u", "m", InputDistribution::uniform, 0.0, 0.0, 2e-6, 6e-6};
  const UncertainInput truncated{"t", "rad", InputDistribution::truncated_normal, 5e-4, 3e-4, 0.0, 1.5e-3};
  const UncertainInput lognormal{"l", "m", InputDistribution::lognormal, 4.5e-7, 1e-7};
  for (const double u : {-3.0, -1.0, 0.0, 0.7, 2.5}) {
    const double p = boost::math::cdf(standard, u);
    EXPECT_NEAR(input_at(uniform, u), 2e-6 + 4e-6 * p, 1e-20);
    // The truncated normal: Φ((x − m)/s) = Φ(a) + p (Φ(b) − Φ(a)).
    const double za = -5.0 / 3.0, zb = 10.0 / 3.0;
    const double x = input_at(truncated, u);
    EXPECT_NEAR(boost::math::cdf(standard, (x - 5e-4) / 3e-4),
                boost::math::cdf(standard, za) + p * (boost::math::cdf(standard, zb) - boost::math::cdf(standard, za)),
                1e-13);
    EXPECT_GE(x, 0.0);
    EXPECT_LE(x, 1.5e-3);
    for (const UncertainInput* in : {&uniform, &truncated, &lognormal}) {
      // Centred difference, h = 1e-5: truncation ~h²·x''' ≪ 1e-8 relative.
      const double h = 1e-5;
      const double difference = (input_at(*in, u + h) - input_at(*in, u - h)) / (2.0 * h);
      EXPECT_NEAR(input_slope(*in, u), difference, 1e-7 * std::abs(difference)) << in->path << " at " << u;
    }
  }
  // The lognormal keeps the input's own mean: E[x] = exp(μ + σ²/2).
  const double sigma = std::sqrt(std::log1p(std::pow(1e-7 / 4.5e-7, 2)));
  EXPECT_NEAR(input_at(lognormal, 0.0) * std::exp(0.5 * sigma * sigma), 4.5e-7, 1e-20);

  // A cut far in the upper tail (8 to 10 sd) keeps its mass: x spans the cut, not stuck
  // at its lower end, and the slope stays positive.
  const UncertainInput far{"f", "1", InputDistribution::truncated_normal, 0.0, 1.0, 8.0, 10.0};
  EXPECT_GT(input_at(far, 0.0), 8.0 + 1e-3);
  EXPECT_LT(input_at(far, 0.0), 8.2);  // the mass is crowded at the lower cut: median ≈ 8 + ln 2/8
  EXPECT_NEAR(input_at(far, 0.0), 8.0 + std::log(2.0) / 8.0, 1e-2);
  EXPECT_GT(input_slope(far, 0.0), 0.0);}

// FORM's gradients take the second-order stencils: exact on a quadratic (to rounding),
// each of them, so a wrong weight or offset shows.
TEST(InputStencils, SecondOrderStencilsAreExactOnQuadratics) {
  const double step = 1e-3, p = 0.7;
  const auto f = [&](double x) { return 3.0 - 2.0 * x + 5.0 * x * x; };
  for (const Stencil* s : {&kCentred2, &kForward2, &kBackward2}) {
    const std::vector<double> d =
        stencil_derivative(*s, step, [&](std::size_t k) { return std::vector<double>{f(p + s->offsets[k] * step)}; });
    EXPECT_NEAR(d[0], -2.0 + 10.0 * p, 1e-9);
  }
}

}  // namespace
}  // namespace twb
