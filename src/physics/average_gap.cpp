#include "twb/physics/average_gap.h"

#include <cmath>
#include <numbers>

namespace twb {

ValueSlope average_gap(double h, double sigma) {
  const double scaled = h / (sigma * std::numbers::sqrt2);
  // 1 + erf(x) = erfc(-x): no cancellation for h << 0, where h_T is tiny but positive.
  const double opened_fraction = 0.5 * std::erfc(-scaled);
  const double gaussian = sigma * std::exp(-scaled * scaled) /
                          std::sqrt(2.0 * std::numbers::pi);
  if (h > 0.0) {
    // h_T = h + [sigma phi(H) - h erfc(x)/2]: the bracket is positive (~ sigma phi/H^2)
    // and is formed from two tiny terms, so h_T >= h holds in floating point too.
    return {h + (gaussian - h * 0.5 * std::erfc(scaled)), opened_fraction};
  }
  return {h * opened_fraction + gaussian, opened_fraction};
}

}  // namespace twb
