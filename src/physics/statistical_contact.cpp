#include "physics/statistical_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "physics/batch_math.h"
#include "twb/error_family.h"

namespace twb {

namespace {

// Relative tolerance of each adaptive Gauss-Kronrod segment: far below the table's
// 1e-8 target, so the table error measured against it is the interpolation error.
constexpr double quadrature_tolerance = 1e-13;
constexpr unsigned quadrature_max_depth = 12;
// The integrand is truncated where the Gaussian has fallen below exp(-72) = 5e-32 of
// its largest value on the integration range (12 standard deviations from its peak).
constexpr double gaussian_reach_sigmas = 12.0;

double standard_normal_density(double x) {
  return std::exp(-0.5 * x * x) / std::sqrt(2.0 * std::numbers::pi);
}

// The two integrals p and dp/dh share every evaluation of the (costly) JG force, so
// they are integrated together as one 2-vector by Boost's Gauss-Kronrod, which accepts
// any integrand type with vector-space operations and a norm abs(). The norm is the
// larger component: both are dimensionless and of comparable size (|dp/dh| sigma_s/p
// ranges over ~0.1..15 on the table), so each gets close to the relative tolerance.
struct PressureMoments {
  double value = 0.0;  // int P g
  double slope = 0.0;  // int P (-(s + delta)) g
  PressureMoments() = default;
  PressureMoments(double v, double s) : value(v), slope(s) {}
  explicit(false) PressureMoments(double both) : value(both), slope(both) {}  // K(0) in Boost
  PressureMoments& operator+=(const PressureMoments& o) {
    value += o.value;
    slope += o.slope;
    return *this;
  }
  friend PressureMoments operator+(PressureMoments a, const PressureMoments& b) { return a += b; }
  friend PressureMoments operator-(const PressureMoments& a, const PressureMoments& b) {
    return {a.value - b.value, a.slope - b.slope};
  }
  friend PressureMoments operator-(const PressureMoments& a) { return {-a.value, -a.slope}; }
  friend PressureMoments operator*(const PressureMoments& a, double k) {
    return {a.value * k, a.slope * k};
  }
  friend PressureMoments operator*(double k, const PressureMoments& a) { return a * k; }
  friend double abs(const PressureMoments& a) {
    return std::max(std::abs(a.value), std::abs(a.slope));
  }
};

// Adaptive Gauss-Kronrod (61 points) over [a, b], mapped onto [-1, 1] first. The map
// matters: Boost 1.74's recursive Gauss-Kronrod compares the error estimate of the
// UNSCALED [-1, 1] rule (floored at 2 eps |integral|/half-width) with a tolerance on the
// scaled integral, so on an interval of half-width below 2 eps/tol (4e-3 for 1e-13) it
// can never converge and recurses to max_depth (seconds per call). On [-1, 1] the
// top level is consistent; at depth k the test is 2^k stricter than asked, still
// reachable for k <= 7 at 1e-13, and the smooth Gaussian-weighted integrands here
// converge well before that.
template <class F>
PressureMoments integrate(F f, double a, double b) {
  if (!(b > a)) return {0.0, 0.0};
  const double middle = 0.5 * (a + b), half_width = 0.5 * (b - a);
  const auto on_unit_interval = [&](double t) { return f(middle + half_width * t); };
  return half_width * boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                          on_unit_interval, -1.0, 1.0, quadrature_max_depth,
                          quadrature_tolerance);
}

}  // namespace

StatisticalContact::StatisticalContact(const JacksonGreenAsperity& asperity,
                                       double summit_density, double summit_sigma,
                                       StatisticalContactTableOptions options)
    : asperity_(asperity), summit_density_(summit_density), summit_sigma_(summit_sigma) {
  if (!(summit_density_ > 0.0) || !(summit_sigma_ > 0.0))
    throw InternalError("StatisticalContact: summit density and sigma must be > 0");
  if (!(options.highest_separation_sigmas > options.lowest_separation_sigmas) ||
      options.nodes_per_sigma < 1 || options.error_check_stride < 1)
    throw InternalError("StatisticalContact: bad table options");
  // Eq [15]: offset between the mean planes of surface heights and of summits.
  mean_summit_offset_ = 0.045944 / (summit_density_ * asperity_.summit_radius());
  build_table(options);
  build_area_table(options);
  cutoff_gap_ = find_cutoff_gap(1e-30);
}

double StatisticalContact::summit_density_from_product(double eta_r_sigma,
                                                       double summit_radius,
                                                       double summit_sigma) {
  return eta_r_sigma / (summit_radius * summit_sigma);
}

template <class Law>
ValueSlope StatisticalContact::summit_integral(Law law, double h) const {
  // Dimensionless interference s = w/sigma_s and separation delta = d/sigma_s:
  //   I     = eta           * int_0^inf law(sigma_s s) g(s + delta) ds
  //   dI/dh = eta / sigma_s * int_0^inf law(sigma_s s) [-(s + delta)] g(s + delta) ds
  // with g the standard normal density.
  const double sigma = summit_sigma_;
  const double delta = (h - mean_summit_offset_) / sigma;
  const double s_transition = asperity_.transition_interference() / sigma;

  const auto integrand = [&](double s) {
    const double weighted = law(sigma * s) * standard_normal_density(s + delta);
    return PressureMoments{weighted, -(s + delta) * weighted};
  };
  // Elastic segment [0, s_t]: P ~ s^1.5 has a singular derivative at 0; with s = u^2
  // the integrand becomes 2u P(u^2) g, smooth (~u^4) for Gauss-Kronrod.
  const auto elastic = [&](double u) { return integrand(u * u) * (2.0 * u); };
  // Elasto-plastic part [s_t, inf): split at the Gaussian's peak (s = -delta) when it
  // lies inside. The JG law jumps at s_t (see asperity_contact.h), which is why s_t is
  // always a segment end. Truncated where (s + delta)^2 exceeds its value at the peak
  // of the range by 2 * 72.
  const double peak = std::max(s_transition, -delta);
  const double reach = gaussian_reach_sigmas;
  const double end = -delta + std::sqrt((peak + delta) * (peak + delta) + reach * reach);

  const PressureMoments moments = integrate(elastic, 0.0, std::sqrt(s_transition)) +
                                  integrate(integrand, s_transition, peak) +
                                  integrate(integrand, peak, end);
  return {summit_density_ * moments.value, summit_density_ / sigma * moments.slope};
}

ValueSlope StatisticalContact::pressure_by_quadrature(double h) const {
  return summit_integral([&](double w) { return asperity_.force(w); }, h);
}

ValueSlope StatisticalContact::real_area_by_quadrature(double h) const {
  return summit_integral([&](double w) { return asperity_.contact_area(w); }, h);
}

namespace {

// ln p and its derivative from the table, continued outside it (see header).
ValueSlope log_pressure(const UniformHermiteTable& table, double sigma, double h) {
  if (h < table.x_first()) {
    const double value = table.node_value(0), slope = table.node_slope(0);
    return {value + slope * (h - table.x_first()), slope};
  }
  if (h > table.x_last()) {
    // Gaussian tail: phi(w + d) ~ exp(-d^2/(2 sigma^2)) dominates ln p far above.
    const std::size_t last = table.size() - 1;
    const double dx = h - table.x_last();
    const double curvature = -1.0 / (sigma * sigma);
    const double slope = table.node_slope(last);
    return {table.node_value(last) + slope * dx + 0.5 * curvature * dx * dx,
            slope + curvature * dx};
  }
  return table.evaluate(h);
}

}  // namespace

void StatisticalContact::pressure(std::span<const double> h, std::span<ValueSlope> out) const {
  constexpr std::size_t chunk = 64;
  std::array<double, chunk> log_p, p;
  for (std::size_t start = 0; start < h.size(); start += chunk) {
    const std::size_t n = std::min(chunk, h.size() - start);
    for (std::size_t k = 0; k < n; ++k) {
      const double hk = h[start + k];
      const ValueSlope l = hk >= table_.x_first() && hk <= table_.x_last() ? table_.evaluate(hk)
                                                                         : log_pressure(table_, summit_sigma_, hk);
      log_p[k] = l.value;
      out[start + k].slope = l.slope;  // d ln p/dh until p is known
    }
    batch::exp(std::span<const double>(log_p.data(), n), std::span<double>(p.data(), n));
    for (std::size_t k = 0; k < n; ++k) out[start + k] = {p[k], p[k] * out[start + k].slope};
  }
}

ValueSlope StatisticalContact::pressure_off_table(double h) const {
  const ValueSlope log_p = log_pressure(table_, summit_sigma_, h);
  const double p = std::exp(log_p.value);
  return {p, p * log_p.slope};
}

void StatisticalContact::build_table(const StatisticalContactTableOptions& options) {
  const double sigma = summit_sigma_;
  const double spacing = sigma / options.nodes_per_sigma;
  const double h_first = mean_summit_offset_ + options.lowest_separation_sigmas * sigma;
  const auto intervals = static_cast<std::size_t>(std::ceil(
      (options.highest_separation_sigmas - options.lowest_separation_sigmas) *
      options.nodes_per_sigma));
  std::vector<double> log_values(intervals + 1), log_slopes(intervals + 1);
  for (std::size_t i = 0; i <= intervals; ++i) {
    const ValueSlope p = pressure_by_quadrature(h_first + spacing * static_cast<double>(i));
    if (!(p.value > 0.0))
      throw std::runtime_error("StatisticalContact: contact pressure underflows in the table");
    log_values[i] = std::log(p.value);
    log_slopes[i] = p.slope / p.value;  // d ln p / dh
  }
  table_ = UniformHermiteTable(h_first, spacing, std::move(log_values), std::move(log_slopes));

  // Error bounds. On an interval the cubic-Hermite error is f''''(xi) dx^4 t^2 (1-t)^2/24:
  // the value error peaks at the midpoint t = 1/2; the slope error (the derivative of
  // that factor, zero at the midpoint) peaks at t = 1/2 -+ 1/(2 sqrt 3). Measure each
  // where it peaks.
  const double slope_check_offset = 0.5 - 0.5 / std::sqrt(3.0);
  table_error_bound_ = 0.0;
  table_slope_error_bound_ = 0.0;
  const auto stride = static_cast<std::size_t>(options.error_check_stride);
  for (std::size_t i = 0; i < intervals; i += stride) {
    const double h_mid = h_first + spacing * (static_cast<double>(i) + 0.5);
    const double exact = pressure_by_quadrature(h_mid).value;
    table_error_bound_ =
        std::max(table_error_bound_, std::abs(pressure(h_mid).value - exact) / exact);
    const double h_slope = h_first + spacing * (static_cast<double>(i) + slope_check_offset);
    const double exact_slope = pressure_by_quadrature(h_slope).slope;
    table_slope_error_bound_ =
        std::max(table_slope_error_bound_,
                 std::abs(pressure(h_slope).slope - exact_slope) / std::abs(exact_slope));
  }
}

double StatisticalContact::find_cutoff_gap(double relative_level) const {
  // ln p is strictly decreasing in h (P increases with interference), so bisect.
  const double target = log_pressure(table_, summit_sigma_, 0.0).value + std::log(relative_level);
  double below = 0.0;
  double above = summit_sigma_;
  while (log_pressure(table_, summit_sigma_, above).value > target) {
    below = above;
    above *= 2.0;
  }
  for (int iteration = 0; iteration < 200 && above - below > 1e-12 * summit_sigma_; ++iteration) {
    const double middle = 0.5 * (below + above);
    (log_pressure(table_, summit_sigma_, middle).value > target ? below : above) = middle;
  }
  return above;
}

void StatisticalContact::build_area_table(const StatisticalContactTableOptions& options) {
  // ln A_r is as smooth as ln p: a quarter of its nodes keeps the Hermite error (∝ spacing⁴)
  // near 1e-7, ample for a flash temperature that goes as A_r^(-1/2) or slower.
  const int per_sigma = std::max(4, options.nodes_per_sigma / 4);
  const double spacing = summit_sigma_ / per_sigma;
  const double h_first = mean_summit_offset_ + options.lowest_separation_sigmas * summit_sigma_;
  const auto intervals = static_cast<std::size_t>(
      std::ceil((options.highest_separation_sigmas - options.lowest_separation_sigmas) * per_sigma));
  std::vector<double> log_values(intervals + 1), log_slopes(intervals + 1);
  for (std::size_t i = 0; i <= intervals; ++i) {
    const ValueSlope a = real_area_by_quadrature(h_first + spacing * static_cast<double>(i));
    if (!(a.value > 0.0)) throw std::runtime_error("StatisticalContact: real contact area underflows in the table");
    log_values[i] = std::log(a.value);
    log_slopes[i] = a.slope / a.value;
  }
  area_table_ = UniformHermiteTable(h_first, spacing, std::move(log_values), std::move(log_slopes));
}

StatisticalContact::SummitContacts StatisticalContact::contacts(double h) const {
  const double d = (h - mean_summit_offset_) / summit_sigma_;
  SummitContacts c;
  c.count = summit_density_ * 0.5 * std::erfc(d / std::numbers::sqrt2);
  const ValueSlope log_area = h >= area_table_.x_first() && h <= area_table_.x_last()
                                  ? area_table_.evaluate(h)
                                  : log_pressure(area_table_, summit_sigma_, h);
  c.area_fraction = std::exp(log_area.value);
  return c;
}

}  // namespace twb
