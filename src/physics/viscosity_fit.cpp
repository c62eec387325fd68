#include "physics/viscosity_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <boost/math/tools/minima.hpp>

namespace twb {

namespace {

constexpr double kCelsius = 273.15;

// Walther's double logarithm of ν (mm²/s).
double walther_z(double nu_mm2) { return std::log10(std::log10(nu_mm2 + 0.7)); }

// The linear least squares of log10(log10 μ − l) on log10(1 + T_C/135) for l = log10 μ∞:
// G0 and S0, and the residual in log10 μ.
struct LinearFit {
  double g0 = 0, s0 = 0, residual = std::numeric_limits<double>::infinity();
};

LinearFit fit_for(double l, const std::vector<ViscosityPoint>& points) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = double(points.size());
  for (const ViscosityPoint& p : points) {
    const double above = std::log10(p.viscosity) - l;
    if (above <= 0) return {};
    const double x = std::log10(1.0 + (p.temperature - kCelsius) / 135.0), y = std::log10(above);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double det = n * sxx - sx * sx;
  if (det <= 0) return {};
  const double slope = (n * sxy - sx * sy) / det, intercept = (sy - slope * sx) / n;
  LinearFit f{std::pow(10.0, intercept), -slope, 0.0};
  for (const ViscosityPoint& p : points) {
    const double a = 1.0 + (p.temperature - kCelsius) / 135.0;
    const double e = l + f.g0 * std::pow(a, -f.s0) - std::log10(p.viscosity);
    f.residual += e * e;
  }
  return f;
}

}  // namespace

double walther_viscosity(double t1, double nu1, double t2, double nu2, double temperature) {
  const double z1 = walther_z(nu1 * 1e6), z2 = walther_z(nu2 * 1e6);
  const double b = (z1 - z2) / (std::log10(t2) - std::log10(t1));
  const double a = z1 + b * std::log10(t1);
  return (std::pow(10.0, std::pow(10.0, a - b * std::log10(temperature))) - 0.7) * 1e-6;
}

ViscosityFit fit_roelands(const std::vector<ViscosityPoint>& points, std::optional<double> mu_infinity) {
  if (points.size() < (mu_infinity ? 2u : 3u))
    throw std::invalid_argument("a Roelands fit needs three points, or two and mu_infinity");
  // μ∞ lies below every viscosity; Roelands' own value for mineral oils is 6.31e-5 Pa s.
  const double least = std::min_element(points.begin(), points.end(), [](auto& a, auto& b) {
                         return a.viscosity < b.viscosity;
                       })->viscosity;
  const double top = std::log10(least) - 1e-3;
  const auto residual = [&](double l) { return fit_for(l, points).residual; };
  std::uintmax_t iterations = 200;
  const double l = mu_infinity ? std::log10(*mu_infinity)
                               : boost::math::tools::brent_find_minima(residual, top - 6.0, top, 40, iterations).first;
  const LinearFit f = fit_for(l, points);
  if (!std::isfinite(f.residual)) throw std::invalid_argument("mu_infinity lies above a viscosity of the table");
  ViscosityFit out;
  out.law = {std::pow(10.0, l), f.g0, f.s0};
  out.points = points;
  for (const ViscosityPoint& p : points) {
    const double e = out.law(p.temperature).value / p.viscosity - 1.0;
    out.relative_errors.push_back(e);
    out.largest_error = std::max(out.largest_error, std::abs(e));
  }
  return out;
}

ViscosityFit fit_data_sheet(double nu40, double nu100, double density, double t_ref, double expansion) {
  const double t40 = kCelsius + 40.0, t100 = kCelsius + 100.0;
  const auto rho = [&](double t) { return density * (1.0 - expansion * (t - t_ref)); };
  std::vector<ViscosityPoint> samples;
  for (int k = 0; k <= 28; ++k) {
    const double t = t40 - 20.0 + k * (60.0 + 20.0 + 60.0) / 28.0;
    samples.push_back({t, rho(t) * walther_viscosity(t40, nu40, t100, nu100, t)});
  }
  ViscosityFit out = fit_roelands(samples);
  out.points = {{t40, rho(t40) * nu40}, {t100, rho(t100) * nu100}};
  out.relative_errors.clear();
  for (const ViscosityPoint& p : out.points)
    out.relative_errors.push_back(out.law(p.temperature).value / p.viscosity - 1.0);
  return out;
}

}  // namespace twb
