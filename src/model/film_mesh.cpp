#include "twb/model/film_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace twb {

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
