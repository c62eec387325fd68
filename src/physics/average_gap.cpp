#include "twb/physics/average_gap.h"

#include <cmath>
#include <numbers>

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

}  // namespace twb
