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
  int threads = 1;         // of the default spread (batch_on_threads)
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

// Where a batch's samples are judged: `judge(sample)` judges one on the calling thread;
// every sample of [first, first + count) is judged somewhere and its verdict returned in
// order, and what the indicator learnt from the batch is made ready for the next ones
// (never for its own: a sample's verdict must not depend on which was judged first).
using JudgeSample = std::function<std::optional<bool>(std::uint64_t sample)>;
using SpreadBatch =
    std::function<std::vector<std::optional<bool>>(std::uint64_t first, std::size_t count, const JudgeSample& judge)>;

// On settings.threads threads of this process, with `between_batches` called after each
// batch.
SpreadBatch batch_on_threads(int threads, std::function<void()> between_batches = {});

// `after_batch` is told the estimate after each batch (a long check's progress).
SamplingEstimate importance_sampling(const FailureIndicator& fails, std::span<const double> centre,
                                     const SamplingSettings& settings, const SpreadBatch& spread,
                                     const std::function<void(const SamplingEstimate&)>& after_batch = {});
inline SamplingEstimate importance_sampling(const FailureIndicator& fails, std::span<const double> centre,
                                            const SamplingSettings& settings) {
  return importance_sampling(fails, centre, settings, batch_on_threads(settings.threads));
}

// Sample i's standard normal variates (its own generator: the same whatever thread draws it).
std::vector<double> standard_normal_sample(std::uint64_t seed, std::uint64_t i, std::size_t dimension);

}  // namespace twb
