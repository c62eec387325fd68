#include "twb/physics/average_gap.h"

#include <cmath>
#include <numbers>

namespace twb {

ValueSlope average_gap(double h, double sigma) {
  const double scaled = h / (sigma * std::numbers::sqrt2);
  // Far open: exp(−x²) and erfc(x) are below the smallest normal double (x > 26.6), so
  // h_T = h and its slope 1 exactly; returning them spares libm's slow subnormal path.
  if (scaled > 27.0) return {h, 1.0};
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
