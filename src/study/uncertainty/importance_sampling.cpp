#include "study/uncertainty/importance_sampling.h"

#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include <boost/math/distributions/normal.hpp>

#include "study/parallel/parallel.h"
#include "twb/error_family.h"

namespace twb {

std::vector<double> standard_normal_sample(std::uint64_t seed, std::uint64_t i, std::size_t dimension) {
  // mt19937_64's sequence is fixed by the standard; the uniform from its top 53 bits and
  // Boost's quantile (not std::normal_distribution, whose algorithm is the library's
  // choice) keep the variates the same on every platform.
  std::seed_seq sequence{std::uint32_t(seed), std::uint32_t(seed >> 32), std::uint32_t(i), std::uint32_t(i >> 32)};
  std::mt19937_64 generator(sequence);
  const boost::math::normal standard;
  std::vector<double> u(dimension);
  for (double& x : u) x = boost::math::quantile(standard, (double(generator() >> 11) + 0.5) * 0x1.0p-53);
  return u;
}

SpreadBatch batch_on_threads(int threads, std::function<void()> between_batches) {
  return [threads, between_batches = std::move(between_batches)](std::uint64_t first, std::size_t count,
                                                                 const JudgeSample& judge) {
    std::vector<std::optional<bool>> verdicts(count);
    run_in_parallel(count, threads, [&](std::size_t k) { verdicts[k] = judge(first + k); });
    if (between_batches) between_batches();
    return verdicts;
  };
}

SamplingEstimate importance_sampling(const FailureIndicator& fails, std::span<const double> centre,
                                     const SamplingSettings& settings, const SpreadBatch& spread,
                                     const std::function<void(const SamplingEstimate&)>& after_batch) {
  const std::size_t n = centre.size();
  const double shift = 0.5 * std::inner_product(centre.begin(), centre.end(), centre.begin(), 0.0);
  SamplingEstimate e;
  double sum = 0.0, sum_squares = 0.0;  // of the weighted indicator
  const int batch = std::max(1, settings.batch);
  while (e.samples < settings.max_samples) {
    const std::size_t count = std::size_t(std::min<long>(batch, settings.max_samples - e.samples));
    const auto sample_u = [&](std::uint64_t sample) {
      std::vector<double> u = standard_normal_sample(settings.seed, sample, n);
      for (std::size_t j = 0; j < n; ++j) u[j] += centre[j];
      return u;
    };
    const std::uint64_t first = std::uint64_t(e.samples);
    const std::vector<std::optional<bool>> verdicts =
        spread(first, count, [&](std::uint64_t sample) { return fails(sample, sample_u(sample)); });
    if (verdicts.size() != count) throw InternalError("importance sampling: a batch's verdicts went missing");
    for (std::size_t k = 0; k < count; ++k) {
      ++e.samples;
      if (!verdicts[k]) {
        ++e.unresolved;
        continue;
      }
      if (!*verdicts[k]) continue;
      // φ(u)/φ(u − u*) = exp(|u*|²/2 − u·u*)
      const std::vector<double> u = sample_u(first + k);
      const double w = std::exp(shift - std::inner_product(u.begin(), u.end(), centre.begin(), 0.0));
      ++e.failures;
      sum += w;
      sum_squares += w * w;
    }
    const double resolved = double(e.samples - e.unresolved);
    if (resolved > 0.0) {
      e.probability = sum / resolved;
      const double variance = std::max(0.0, sum_squares / resolved - e.probability * e.probability) / resolved;
      e.cov = e.probability > 0.0 ? std::sqrt(variance) / e.probability : std::numeric_limits<double>::infinity();
      e.low = std::max(0.0, e.probability - 1.96 * std::sqrt(variance));
      e.high = e.probability + 1.96 * std::sqrt(variance);
    }
    if (after_batch) after_batch(e);
    if (e.samples >= settings.min_samples && e.cov <= settings.cov) {
      e.reached = true;
      break;
    }
  }
  return e;
}

}  // namespace twb
