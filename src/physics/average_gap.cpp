#include "physics/average_gap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "physics/batch_math.h"

namespace twb {

ValueSlope average_gap(double h, double sigma) {
  const double scaled = h / (sigma * std::numbers::sqrt2);
  // Open by more than 6√2 σ (h/σ > 8.49, most of a tilted film), the closed form rounds
  // to {h, 1} exactly, so it is returned without its exp and erfc: the closed fraction
  // erfc(x)/2 ≤ erfc(6)/2 = 1.1e-17 is below half an ulp of 1 (2^-54 = 5.6e-17), so
  // 1 − closed rounds to 1; the bracket below is at most σφ(x√2) ≤ 9.2e-17 σ, i.e.
  // 1.1e-17 of h, below half an ulp of h, so h + bracket rounds to h.
  if (scaled >= exact_open_threshold) return {h, 1.0};
  const double gaussian = sigma * std::exp(-scaled * scaled) /
                          std::sqrt(2.0 * std::numbers::pi);
  if (h > 0.0) {
    // One erfc serves both: erfc(x) is the small closed fraction, 1 − erfc(x)/2 the
    // opened one (no cancellation: erfc(x)/2 < 1/2). h_T = h + [sigma phi(H) − h erfc(x)/2]:
    // the bracket is positive (~ sigma phi/H^2) and is formed from two tiny terms, so
    // h_T >= h holds in floating point too.
    const double closed = 0.5 * std::erfc(scaled);
    return {h + (gaussian - h * closed), 1.0 - closed};
  }
  // 1 + erf(x) = erfc(−x): no cancellation for h << 0, where h_T is tiny but positive.
  const double opened_fraction = 0.5 * std::erfc(-scaled);
  return {h * opened_fraction + gaussian, opened_fraction};
}

double average_gap_curvature(double h, double sigma) {
  const double scaled = h / (sigma * std::numbers::sqrt2);
  if (scaled >= exact_open_threshold) return 0.0;
  return std::exp(-scaled * scaled) / (sigma * std::sqrt(2.0 * std::numbers::pi));
}

void average_gap(std::span<const double> h, double sigma, std::span<ValueSlope> out) {
  // The scalar function's arithmetic, with its exp and erfc taken over the batch; points
  // open beyond the threshold get {h, 1} as there (their lanes compute a dummy value).
  constexpr std::size_t chunk = 64;
  std::array<double, chunk> scaled, square, gaussian, tail;
  for (std::size_t start = 0; start < h.size(); start += chunk) {
    const std::size_t n = std::min(chunk, h.size() - start);
    for (std::size_t k = 0; k < n; ++k) {
      scaled[k] = h[start + k] / (sigma * std::numbers::sqrt2);
      const double x = scaled[k] >= exact_open_threshold ? 0.0 : scaled[k];
      square[k] = -x * x;
      tail[k] = std::abs(x);  // erfc(x) where h > 0, erfc(−x) where h ≤ 0
    }
    batch::exp(std::span<const double>(square.data(), n), std::span<double>(gaussian.data(), n));
    batch::erfc(std::span<const double>(tail.data(), n), std::span<double>(tail.data(), n));
    for (std::size_t k = 0; k < n; ++k) {
      const double hk = h[start + k];
      if (scaled[k] >= exact_open_threshold) {
        out[start + k] = {hk, 1.0};
        continue;
      }
      const double g = sigma * gaussian[k] / std::sqrt(2.0 * std::numbers::pi);
      if (hk > 0.0) {
        const double closed = 0.5 * tail[k];
        out[start + k] = {hk + (g - hk * closed), 1.0 - closed};
      } else {
        const double opened_fraction = 0.5 * tail[k];
        out[start + k] = {hk * opened_fraction + g, opened_fraction};
      }
    }
  }
}

double average_gap_by_sigma(double h, double sigma) {
  const double x = h / sigma;
  return std::exp(-0.5 * x * x) / std::sqrt(2.0 * std::numbers::pi);
}

double average_gap_slope_by_sigma(double h, double sigma) {
  const double x = h / sigma;
  return -x * std::exp(-0.5 * x * x) / (sigma * std::sqrt(2.0 * std::numbers::pi));
}

}  // namespace twb
