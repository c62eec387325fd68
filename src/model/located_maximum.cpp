#include "model/located_maximum.h"

#include <algorithm>
#include <cmath>

#include <boost/math/tools/minima.hpp>

namespace twb {

namespace {
// Brent's search locates an interior maximum to about √ε of its bracket: the value, flat
// there, to ε. At an end of the bracket (the rim) it closes on the end to that width.
constexpr int kBits = 26;
// Alternating searches along θ and r: the second sweep moves a point by far less than the
// first on a smooth hump, a third is a check that rarely moves it.
constexpr int kSweeps = 3;
}  // namespace

LocatedMaximum locate_maximum(const std::vector<Film>& films,
                              const std::function<double(const Film&, double, double)>& value,
                              const std::function<bool(const Film&)>& applies) {
  LocatedMaximum best;
  bool found = false;
  for (const Film& film : films) {
    if (!applies(film)) continue;
    const FilmMesh& m = film.mesh;
    // The hottest node, the search's start.
    double top = -HUGE_VAL;
    int ti = 0, tj = 0;
    for (int i = 0; i < m.radial_nodes(); ++i)
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        const double v = value(film, m.radius(i), m.angle(j));
        if (v > top) top = v, ti = i, tj = j;
      }
    double r = m.radius(ti), theta = m.angle(tj);
    const double r_low = m.radius(std::max(ti - 1, 0)), r_high = m.radius(std::min(ti + 1, m.radial_nodes() - 1));
    const double th_low = theta - m.dtheta(), th_high = theta + m.dtheta();
    for (int sweep = 0; sweep < kSweeps; ++sweep) {
      const auto along_theta = boost::math::tools::brent_find_minima(
          [&](double th) { return -value(film, r, th); }, th_low, th_high, kBits);
      if (-along_theta.second > top) top = -along_theta.second, theta = along_theta.first;
      if (r_high > r_low) {
        const auto along_r = boost::math::tools::brent_find_minima(
            [&](double rr) { return -value(film, rr, theta); }, r_low, r_high, kBits);
        if (-along_r.second > top) top = -along_r.second, r = along_r.first;
      }
    }
    // Brent's end points lie a tolerance inside its bracket: the rim itself is a candidate.
    for (double edge : {r_low, r_high}) {
      const double v = value(film, edge, theta);
      if (v > top) top = v, r = edge;
    }
    if (!found || top > best.value) best = {top, film.number, r, theta < 0 ? theta + 2 * M_PI : theta};
    found = true;
  }
  return best;
}

}  // namespace twb
