// Running-in by truncation (docs/physics.md section 20, [W5]-[W6]): against a synthetic
// Gaussian face cut flat, the inverse of [W5], the exact slope dRq/dd, and where
// running-in stops.
#include "physics/running_in.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace twb {
namespace {

// A face of two million Gaussian heights (unit Rq) cut at τ: the mean depth removed and
// the plateau face's variance are [W5] and [W6] to the sample's statistical error. The
// error of a mean of n draws is their spread over sqrt(n), that of a variance
// sqrt((m4 − var²)/n) with m4 the fourth central moment: five of them bound the
// difference (a chance of 6e-7 each, for a correct formula).
TEST(RunningIn, ACutGaussianFaceLosesW5AndKeepsW6) {
  std::mt19937_64 engine(20260401);
  std::normal_distribution<double> height;
  std::vector<double> z(2'000'000);
  for (double& x : z) x = height(engine);
  const double n = double(z.size());
  for (const double cut : {-1.5, -0.5, 0.0, 0.7, 1.5, 2.5}) {
    SCOPED_TRACE(cut);
    double removed = 0.0, removed_sq = 0.0, mean = 0.0;
    for (const double x : z) {
      const double r = std::max(x - cut, 0.0);
      removed += r;
      removed_sq += r * r;
      mean += std::min(x, cut);
    }
    removed /= n;
    mean /= n;
    double m2 = 0.0, m4 = 0.0;
    for (const double x : z) {
      const double c = std::min(x, cut) - mean;
      m2 += c * c;
      m4 += c * c * c * c;
    }
    m2 /= n;
    m4 /= n;
    const double removed_error = std::sqrt((removed_sq / n - removed * removed) / n);
    const double variance_error = std::sqrt((m4 - m2 * m2) / n);
    EXPECT_NEAR(truncated_depth(cut), removed, 5.0 * removed_error);
    EXPECT_NEAR(truncated_variance(cut), m2, 5.0 * variance_error);
  }
}

// [W5] limits: no cut removes nothing; a cut far below the mean removes −τ.
TEST(RunningIn, W5GoesFromNothingToTheCutBelowTheMean) {
  EXPECT_LT(truncated_depth(RunningIn::kHighestCut), 1e-17);
  EXPECT_GT(truncated_variance(RunningIn::kHighestCut), 1.0 - 1e-15);
  EXPECT_NEAR(truncated_depth(-12.0), 12.0, 1e-12);
  // far below, the plateau face is flat: [W6] is 2φ/|τ|³ to leading order (relative
  // 1/τ² next), computed without the cancellation of [W6]'s terms of size τ²
  const double tau = -8.0, phi = std::exp(-0.5 * tau * tau) / std::sqrt(2.0 * M_PI);
  EXPECT_NEAR(truncated_variance(tau), 2.0 * phi / std::pow(-tau, 3), 10.0 / (tau * tau) * 2.0 * phi / std::pow(-tau, 3));
}

// cut_for_depth inverts [W5] (Newton to 1e-15 of the cut; [W5]'s slope Q is at least
// 1e-18 there, so the depth to a few ulp of itself where the cut is below 8).
TEST(RunningIn, TheCutOfADepthRemovesThatDepth) {
  for (const double depth : {1e-12, 1e-6, 1e-3, 0.05, 0.4, 1.0, 3.0, 30.0}) {
    SCOPED_TRACE(depth);
    const double cut = cut_for_depth(depth);
    EXPECT_NEAR(truncated_depth(cut), depth, 1e-12 * depth);
  }
  EXPECT_EQ(cut_for_depth(0.0), RunningIn::kHighestCut);
  EXPECT_EQ(cut_for_depth(-1.0), RunningIn::kHighestCut);
}

// dRq/dd = −(τΦ + φ)/sqrt([W6]) against central differences of Rq (step 1e-5 of the
// depth: truncation error O(step²·Rq''') about 1e-10 relative; rounding, each Rq within
// a few ulp of σ0, 4ε·σ0/step absolute).
TEST(RunningIn, TheSlopeOfRqInTheDepthIsExact) {
  const double rq = 0.5e-6;
  const RunningIn face(rq, 0.1e-6);
  for (const double depth : {1e-12, 1e-10, 5e-9, 0.05e-6, 0.3e-6, 0.6e-6}) {
    SCOPED_TRACE(depth);
    ASSERT_LT(depth, *face.run_in_depth());
    const double step = 1e-5 * depth;
    const double slope = (face.rq(depth + step).value - face.rq(depth - step).value) / (2.0 * step);
    EXPECT_NEAR(face.rq(depth).slope, slope, 1e-9 * std::abs(slope) + 4.0 * 2.2e-16 * rq / step);
  }
}

// Running-in stops where [W6] reaches the run-in Rq; from there the face keeps it. A face
// without one keeps its Rq, and a new face (no depth, or IDA's negative round-off) has it.
TEST(RunningIn, RunningInStopsAtTheRunInRq) {
  const double rq = 0.5e-6, run_in = 0.2e-6;
  const RunningIn face(rq, run_in);
  ASSERT_TRUE(face.run_in_depth());
  const double stop = *face.run_in_depth();
  EXPECT_NEAR(face.rq(stop * (1.0 - 1e-9)).value, run_in, 1e-8 * run_in);
  EXPECT_EQ(face.rq(stop).value, run_in);
  EXPECT_EQ(face.rq(10.0 * stop).value, run_in);
  EXPECT_EQ(face.rq(10.0 * stop).slope, 0.0);
  EXPECT_NEAR(face.rq(0.0).value, rq, 1e-15 * rq);
  EXPECT_NEAR(face.rq(-1e-12).value, rq, 1e-15 * rq);
  EXPECT_LT(face.rq(0.5 * stop).value, rq);
  EXPECT_GT(face.rq(0.5 * stop).value, run_in);
  const RunningIn kept(rq, std::nullopt);
  EXPECT_FALSE(kept.run_in_depth());
  EXPECT_EQ(kept.rq(3e-6).value, rq);
  EXPECT_EQ(kept.rq(3e-6).slope, 0.0);
  const RunningIn already(rq, rq);
  EXPECT_EQ(*already.run_in_depth(), 0.0);
  EXPECT_THROW(RunningIn(rq, 2.0 * rq), std::invalid_argument);
  EXPECT_THROW(RunningIn(-rq, std::nullopt), std::invalid_argument);
}

}  // namespace
}  // namespace twb
