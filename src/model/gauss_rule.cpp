#include "model/gauss_rule.h"
#include "twb/error_family.h"

#include <stdexcept>

#include <boost/math/quadrature/gauss.hpp>

namespace twb {

namespace {
template <int N>
GaussRule gauss_rule() {
  // Boost stores the non-negative abscissae of the rule on [-1, 1].
  using Rule = boost::math::quadrature::gauss<double, N>;
  GaussRule rule;
  const auto& x = Rule::abscissa();
  const auto& w = Rule::weights();
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (x[k] == 0.0) {
      rule.points.push_back(0.5);
      rule.weights.push_back(0.5 * w[k]);
    } else {
      rule.points.push_back(0.5 * (1.0 - x[k]));
      rule.weights.push_back(0.5 * w[k]);
      rule.points.push_back(0.5 * (1.0 + x[k]));
      rule.weights.push_back(0.5 * w[k]);
    }
  }
  return rule;
}
}  // namespace

GaussRule GaussRule::legendre(int n) {
  switch (n) {
    case 1: return gauss_rule<1>();
    case 2: return gauss_rule<2>();
    case 3: return gauss_rule<3>();
    case 4: return gauss_rule<4>();
    case 5: return gauss_rule<5>();
    case 6: return gauss_rule<6>();
    case 7: return gauss_rule<7>();
    case 8: return gauss_rule<8>();
    case 10: return gauss_rule<10>();
    case 12: return gauss_rule<12>();
    case 16: return gauss_rule<16>();
    case 20: return gauss_rule<20>();
    default: throw InternalError("Gauss-Legendre rule with this many points is not available");
  }
}

}  // namespace twb
