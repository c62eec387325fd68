#include "twb/model/film_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
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
    default: throw std::invalid_argument("Gauss-Legendre rule with this many points is not available");
  }
}

FilmMesh::FilmMesh(double inner_radius, double outer_radius, int radial_nodes, int circumferential_nodes)
    : r_in_(inner_radius), r_out_(outer_radius), nr_(radial_nodes), nt_(circumferential_nodes) {
  if (!(outer_radius > inner_radius) || radial_nodes < 2 || circumferential_nodes < 3)
    throw std::invalid_argument("FilmMesh: empty annulus or too few nodes");
  dr_ = (r_out_ - r_in_) / (nr_ - 1);
  dtheta_ = 2.0 * std::numbers::pi / nt_;
  node_area_.resize(nr_);
  for (int i = 0; i < nr_; ++i) {
    // ∫ hat r dr over each adjacent interval: Δr·(2 r_i + r_other)/6.
    double a = 0.0;
    if (i > 0) a += dr_ * (2.0 * radius(i) + radius(i - 1)) / 6.0;
    if (i < nr_ - 1) a += dr_ * (2.0 * radius(i) + radius(i + 1)) / 6.0;
    node_area_[i] = a * dtheta_;
  }
}

double FilmMesh::area() const { return std::numbers::pi * (r_out_ * r_out_ - r_in_ * r_in_); }

FilmMesh::RadialWeights FilmMesh::radial_weights(double r) const {
  const double s = std::clamp((r - r_in_) / dr_, 0.0, double(nr_ - 1));
  const int i0 = std::min(int(std::floor(s)), nr_ - 2);
  const double t = s - i0;
  return {i0, 1.0 - t, i0 + 1, t};
}

}  // namespace twb
