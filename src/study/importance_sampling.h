// The Monte Carlo check of FORM (docs/physics.md section 17): importance sampling in the
// standard normal space round the design point u* (Melchers 1989): samples u from
// φ(u − u*), each weighted by φ(u)/φ(u − u*) = exp(|u*|²/2 − u·u*), so that a failure
// probability of 1e-3 is estimated from hundreds of samples rather than the 10⁵ plain
// sampling needs. Samples are drawn in batches until the estimate's coefficient of
// variation is the one asked for; sample i's variates come from its own generator
// seeded by (seed, i), so the estimate does not depend on the thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace twb {

struct SamplingSettings {
  double cov = 0.1;        // the coefficient of variation to reach
  int min_samples = 100;   // before the first verdict on it
  int max_samples = 4000;
  int batch = 50;          // samples between verdicts (and the unit threads share)
  std::uint64_t seed = 1;
  int threads = 1;
};

// Whether the bearing at u, sample number `sample`, fails; none where it cannot be told
// (the sample is counted as unresolved, and left out).
using FailureIndicator = std::function<std::optional<bool>(std::uint64_t sample, std::span<const double> u)>;

struct SamplingEstimate {
  double probability = 0.0;
  double cov = 0.0;                // of the estimate (infinite without a failure)
  double low = 0.0, high = 0.0;    // its 95 % confidence interval (normal approximation)
  long samples = 0, failures = 0, unresolved = 0;
  bool reached = false;            // cov reached within max_samples
};

// `between_batches` is called after each batch's samples, before the next batch's (what
// the indicator learnt from a batch may serve the next ones, never its own).
SamplingEstimate importance_sampling(const FailureIndicator& fails, std::span<const double> centre,
                                     const SamplingSettings& settings, const std::function<void()>& between_batches = {});

// Sample i's standard normal variates (its own generator: the same whatever thread draws it).
std::vector<double> standard_normal_sample(std::uint64_t seed, std::uint64_t i, std::size_t dimension);

}  // namespace twb
