// The semismooth functions the model writes its complementarity rows with (the film's
// cavitation, docs/physics.md section 3; the gear's stop, section 19).
#pragma once

#include <cmath>

#include "model/bearing_model.h"

namespace twb {

// φ(a, b) and its partial derivatives: Fischer–Burmeister a + b − √(a² + b²) or
// min(a, b). At their kinks (FB at (0, 0), min where a = b) any element of the
// generalized Jacobian serves semismooth Newton.
//
// Where a ≫ |b| with a > 0 (a gear far from its stop, a node deep in the cavitated zone)
// the sum a + b − √(a² + b²) cancels to ≈ b − b²/(2a), losing the rounding of a, and
// 1 − a/n cancels alike: written 2ab/(a + b + n) and b²/(n·(n + a)) instead (the same
// numbers, (a + b)² − n² = 2ab), they keep their relative precision.
struct Complementarity {
  double value, da, db;
};
inline Complementarity complementarity(CavitationRow row, double a, double b) {
  if (row == CavitationRow::minimum) return a <= b ? Complementarity{a, 1.0, 0.0} : Complementarity{b, 0.0, 1.0};
  const double n = std::hypot(a, b);
  if (n == 0.0) return {0.0, 1.0 - std::sqrt(0.5), 1.0 - std::sqrt(0.5)};
  const double value = a + b > 0.0 ? 2.0 * a * b / (a + b + n) : a + b - n;
  // Each factor at most 1: no under- or overflow where n is tiny or huge.
  const double da = a > 0.0 ? (b / n) * (b / (n + a)) : 1.0 - a / n;
  const double db = b > 0.0 ? (a / n) * (a / (n + b)) : 1.0 - b / n;
  return {value, da, db};
}

}  // namespace twb
