// Gauss–Legendre rules on [0, 1], for the integrals over a film's cells (docs/model.md,
// "Integrals over cells").
#pragma once

#include <vector>

namespace twb {

struct GaussRule {
  std::vector<double> points;   // on [0, 1]
  std::vector<double> weights;  // sum to 1
  static GaussRule legendre(int n);
};

}  // namespace twb
