// Statistical elasto-plastic contact pressure, docs/physics.md section 4 / paper eqs [13]-[15].
#include "physics/statistical_contact.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <gtest/gtest.h>
#include "twb/error_family.h"

namespace {

// docs/physics.md defaults: sigma_s = sigma = sqrt(2) * 0.515 um (two Table 1 surfaces),
// R = 20 um, eta R sigma_s = 0.05, Table 1 steel.
constexpr double summit_sigma = std::numbers::sqrt2 * 0.515e-6;
constexpr double summit_radius = 20e-6;

twb::JacksonGreenAsperity table1_asperity() {
  return {twb::JacksonGreenAsperity::effective_modulus(201e9, 0.296, 201e9, 0.296), 0.993e9,
          0.296, summit_radius};
}

double default_density() {
  return twb::StatisticalContact::summit_density_from_product(0.05, summit_radius, summit_sigma);
}

// Built once for the whole suite (construction cost is reported by one test).
const twb::StatisticalContact& contact() {
  static const twb::StatisticalContact instance(table1_asperity(), default_density(), summit_sigma);
  return instance;
}

// Independent reference: the paper's form [13], p = eta int_d^inf P(z - d) phi(z) dz,
// in zeta = z/sigma_s with Boost's tanh-sinh (double-exponential) rule, split at the
// JG transition z = d + 1.9 w_c and at the Gaussian's centre z = 0.
double pressure_by_tanh_sinh(double h) {
  const auto asperity = table1_asperity();
  const double eta = default_density();
  const double d = (h - 0.045944 / (eta * summit_radius)) / summit_sigma;
  const double transition = d + asperity.transition_interference() / summit_sigma;
  const auto integrand = [&](double zeta) {
    return asperity.force(summit_sigma * (zeta - d)) * std::exp(-0.5 * zeta * zeta) /
           std::sqrt(2.0 * std::numbers::pi);
  };
  boost::math::quadrature::tanh_sinh<double> rule(12);
  const auto piece = [&](double a, double b) {
    return b > a ? rule.integrate(integrand, a, b, 1e-15) : 0.0;
  };
  const double centre = std::max(transition, 0.0);
  return eta * (piece(d, transition) + piece(transition, centre) + piece(centre, centre + 13.0));
}

TEST(StatisticalContact, PressureAtZeroGapIsAsModelStates) {
  const double p0 = contact().pressure(0.0).value;
  std::cout << "[ p_cont(0) ] table " << std::setprecision(12) << p0 << " Pa, quadrature "
            << contact().pressure_by_quadrature(0.0).value << " Pa\n";
  EXPECT_GE(p0, 5e8);
  EXPECT_LE(p0, 1e9);
  // Independent 30-digit mpmath evaluation of eq [13]: 704453331.790150485 Pa.
  EXPECT_NEAR(contact().pressure_by_quadrature(0.0).value / 704453331.790150485, 1.0, 1e-11);
  EXPECT_NEAR(p0 / 704453331.790150485, 1.0, 1e-8);
}

TEST(StatisticalContact, QuadratureMatchesIndependentHighPrecisionValues) {
  // mpmath, 30 digits: value (Pa) and dp/dh (Pa/m) at h = -3, 0, 3 sigma_s.
  struct Reference { double h_sigmas, p, dp_dh; };
  for (const Reference& r : {Reference{-3.0, 2720490362.87803592, -885917417951880.039},
                             Reference{0.0, 704453331.790150485, -808905508955450.541},
                             Reference{3.0, 4118213.14445355531, -15819807842350.9830}}) {
    const auto q = contact().pressure_by_quadrature(r.h_sigmas * summit_sigma);
    EXPECT_NEAR(q.value / r.p, 1.0, 1e-11) << r.h_sigmas;
    EXPECT_NEAR(q.slope / r.dp_dh, 1.0, 1e-11) << r.h_sigmas;
  }
}

TEST(StatisticalContact, TableErrorBoundIsSmall) {
  const auto timed_build = [](twb::StatisticalContactTableOptions options) {
    const auto start = std::chrono::steady_clock::now();
    twb::StatisticalContact built(table1_asperity(), default_density(), summit_sigma, options);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return std::pair{built, ms};
  };
  const auto [fresh, default_ms] = timed_build({});
  twb::StatisticalContactTableOptions check_all;
  check_all.error_check_stride = 1;
  const auto [fully_checked, full_ms] = timed_build(check_all);
  std::cout << "[ table ] " << fresh.log_pressure_table().size() << " nodes over h in ["
            << fresh.log_pressure_table().x_first() / summit_sigma << ", "
            << fresh.log_pressure_table().x_last() / summit_sigma << "] sigma_s; built in "
            << default_ms << " ms (checking every "
            << twb::StatisticalContactTableOptions{}.error_check_stride << "th interval), " << full_ms
            << " ms (checking all); error bound " << fresh.table_error_bound() << " / "
            << fully_checked.table_error_bound() << " (value), "
            << fresh.table_slope_error_bound() << " / "
            << fully_checked.table_slope_error_bound() << " (slope); cutoff gap "
            << fresh.contact_pressure_cutoff_gap() / summit_sigma << " sigma_s\n";
  EXPECT_LT(fully_checked.table_error_bound(), 1e-8);
  EXPECT_LT(fully_checked.table_slope_error_bound(), 1e-6);
  EXPECT_LE(fresh.table_error_bound(), fully_checked.table_error_bound());
  EXPECT_LT(fresh.table_error_bound(), 1e-8);
  EXPECT_GT(fresh.table_error_bound(), 0.0);  // it was measured
  EXPECT_LT(fresh.table_slope_error_bound(), 1e-6);
  // Halving the spacing must cut the value error ~16x (cubic Hermite is 4th order):
  // proves the bound measures interpolation, not quadrature noise.
  twb::StatisticalContactTableOptions coarse;
  coarse.nodes_per_sigma = 16;
  coarse.error_check_stride = 1;
  const twb::StatisticalContact coarser(table1_asperity(), default_density(), summit_sigma, coarse);
  EXPECT_NEAR(coarser.table_error_bound() / fully_checked.table_error_bound(), 16.0, 4.0);
  EXPECT_NEAR(coarser.table_slope_error_bound() / fully_checked.table_slope_error_bound(), 8.0, 2.0);
}

TEST(StatisticalContact, TableMatchesIndependentQuadratureAtRandomGaps) {
  std::mt19937 generator(20060101);
  const auto& table = contact().log_pressure_table();
  std::uniform_real_distribution<double> gap(table.x_first(), table.x_last());
  for (int sample = 0; sample < 20; ++sample) {
    const double h = gap(generator);
    const double reference = pressure_by_tanh_sinh(h);
    EXPECT_NEAR(contact().pressure(h).value / reference, 1.0, 1e-8) << "h/sigma = " << h / summit_sigma;
    EXPECT_NEAR(contact().pressure_by_quadrature(h).value / reference, 1.0, 1e-11)
        << "h/sigma = " << h / summit_sigma;
    // The table's slope error is O(spacing^3) (~4e-8 for the defaults): bound 1e-6.
    EXPECT_NEAR(contact().pressure(h).slope / contact().pressure_by_quadrature(h).slope, 1.0,
                1e-6) << "h/sigma = " << h / summit_sigma;
  }
}

TEST(StatisticalContact, QuadratureSlopeMatchesCentralDifferencesOfQuadrature) {
  // Checks the phi' form of dp/dh. Step 1e-4 sigma_s: truncation ~ p''' step^2/6 ~
  // 1e-8 * (sigma_s^3 |p'''|/|p'|, at most ~30 here) and quadrature noise
  // ~1e-13/1e-4 = 1e-9, relative: bound 1e-6.
  for (double H : {-9.0, -4.0, -1.0, 0.0, 0.92, 2.0, 5.0, 9.0, 12.0}) {
    const double h = H * summit_sigma, step = 1e-4 * summit_sigma;
    const double fd = (contact().pressure_by_quadrature(h + step).value -
                       contact().pressure_by_quadrature(h - step).value) / (2 * step);
    EXPECT_NEAR(contact().pressure_by_quadrature(h).slope / fd, 1.0, 1e-6) << H;
  }
}

TEST(StatisticalContact, TableSlopeIsItsExactDerivativeAndMatchesQuadrature) {
  // Against central differences of the table itself: the slope must be the derivative
  // of the interpolant. Step 1e-5 sigma_s: truncation ~1e-10 sigma_s^3 p'''/p', at most
  // ~2e4 far up the tail (d ~ 13 sigma: (ln p)' ~ 13/sigma), roundoff 1e-16/1e-5:
  // bound 1e-5 relative.
  for (double H = -12.0; H <= 16.0; H += 0.173) {
    const double h = H * summit_sigma, step = 1e-5 * summit_sigma;
    const double fd = (contact().pressure(h + step).value - contact().pressure(h - step).value) /
                      (2 * step);
    ASSERT_NEAR(contact().pressure(h).slope / fd, 1.0, 1e-5) << H;
  }
  // Against the quadrature's phi' integral inside the table: the Hermite derivative
  // error is O(spacing^3), one order above the value's; 1e-6 relative.
  for (double H : {-8.5, -2.0, 0.0, 0.5, 3.3, 7.7, 11.9}) {
    const double h = H * summit_sigma;
    EXPECT_NEAR(contact().pressure(h).slope / contact().pressure_by_quadrature(h).slope, 1.0,
                1e-6) << H;
  }
}

TEST(StatisticalContact, ContinuationOutsideTableIsC1MonotoneAndFinite) {
  const auto& table = contact().log_pressure_table();
  for (double edge : {table.x_first(), table.x_last()}) {
    const double tiny = 1e-9 * summit_sigma;
    const auto inside = contact().pressure(edge == table.x_first() ? edge + tiny : edge - tiny);
    const auto outside = contact().pressure(edge == table.x_first() ? edge - tiny : edge + tiny);
    EXPECT_NEAR(outside.value / inside.value, 1.0, 1e-7);
    EXPECT_NEAR(outside.slope / inside.slope, 1.0, 1e-7);
  }
  double previous = std::numeric_limits<double>::infinity();
  for (double H = -40.0; H <= 60.0; H += 0.01) {
    const auto p = contact().pressure(H * summit_sigma);
    ASSERT_TRUE(std::isfinite(p.value) && std::isfinite(p.slope)) << H;
    ASSERT_GE(p.value, 0.0) << H;
    ASSERT_LE(p.slope, 0.0) << H;
    if (previous > std::numeric_limits<double>::min()) {
      ASSERT_LT(p.value, previous) << H;  // strictly, until exp() underflows
    }
    previous = p.value;
  }
  // Just above the table, the Gaussian-tail continuation is still close to the integral.
  const double h = table.x_last() + 0.5 * summit_sigma;
  EXPECT_NEAR(contact().pressure(h).value / pressure_by_tanh_sinh(h), 1.0, 0.1);
}

TEST(StatisticalContact, CutoffGap) {
  const double cutoff = contact().contact_pressure_cutoff_gap();
  const double p0 = contact().pressure(0.0).value;
  EXPECT_NEAR(contact().pressure(cutoff).value / (1e-30 * p0), 1.0, 1e-6);
  EXPECT_NEAR(pressure_by_tanh_sinh(cutoff) / (1e-30 * p0), 1.0, 1e-6);
  EXPECT_LT(contact().pressure(cutoff * 1.001).value, 1e-30 * p0);
}

TEST(StatisticalContact, TableLookupIsFast) {
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> gap(-2 * summit_sigma, 8 * summit_sigma);
  constexpr int calls = 1'000'000;
  double sum = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < calls; ++i) sum += contact().pressure(gap(generator)).value;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[ lookup ] " << seconds / calls * 1e9 << " ns per pressure() call (with RNG)\n";
  EXPECT_GT(sum, 0.0);
}

TEST(StatisticalContact, RejectsBadParameters) {
  EXPECT_THROW(twb::StatisticalContact(table1_asperity(), 0.0, summit_sigma), twb::InternalError);
  EXPECT_THROW(twb::StatisticalContact(table1_asperity(), default_density(), -1.0), twb::InternalError);
}

TEST(StatisticalContact, BatchPressureEqualsScalarOnAndOffTheTable) {
  // Below the table, on it and in the Gaussian tail above it; the batch's exp is
  // vectorized (a few ulp), its table lookup the same.
  const twb::StatisticalContact& c = contact();
  const double lo = c.log_pressure_table().x_first(), hi = c.log_pressure_table().x_last();
  std::vector<double> h;
  for (int k = 0; k <= 200; ++k) h.push_back(lo - 0.5 * summit_sigma + (hi - lo + summit_sigma) * k / 200.0);
  std::vector<twb::ValueSlope> p(h.size());
  c.pressure(h, p);
  for (std::size_t k = 0; k < h.size(); ++k) {
    const twb::ValueSlope one = c.pressure(h[k]);
    EXPECT_NEAR(p[k].value / one.value, 1.0, 1e-14) << "h = " << h[k];
    EXPECT_NEAR(p[k].slope / one.slope, 1.0, 1e-14) << "h = " << h[k];
  }
}

}  // namespace

// The summits in contact (scuffing, docs/physics.md section 8): the real area from its
// table against the direct quadrature (the table's Hermite error at 8 nodes per σs is
// below 1e-7 of A_r; 1e-6 allows for where the two differ most, far above the table),
// and the count the Gaussian tail of the summit heights above the separation.
TEST(StatisticalContact, SummitContactsFromTheirTableAndTheirTail) {
  const twb::StatisticalContact& c = contact();
  for (double h_sigmas : {-2.0, -0.5, 0.0, 0.7, 1.5, 3.0, 5.0}) {
    const double h = h_sigmas * summit_sigma;
    const auto summits = c.contacts(h);
    const double exact = c.real_area_by_quadrature(h).value;
    EXPECT_NEAR(summits.area_fraction, exact, 1e-6 * exact) << h_sigmas;
    const double d = (h - c.mean_summit_offset()) / summit_sigma;
    EXPECT_NEAR(summits.count, default_density() * 0.5 * std::erfc(d / std::numbers::sqrt2),
                1e-12 * summits.count);
    // The mean contact: area over count, a radius below the summit's own.
    const double radius = std::sqrt(summits.area_fraction / (std::numbers::pi * summits.count));
    EXPECT_GT(radius, 0.0);
    EXPECT_LT(radius, summit_radius) << h_sigmas;
  }
}

// The JG contact area: Hertz's π R ω while elastic; beyond, the radius eq [10] gives,
// a/R = (π C e_y/2)·sqrt(ω*)·(ω*/1.9)^(B/2), written here from the paper's symbols.
TEST(JacksonGreenAsperity, ContactAreaIsHertzsThenEquationTen) {
  const twb::JacksonGreenAsperity a = table1_asperity();
  const double wc = a.critical_interference();
  EXPECT_NEAR(a.contact_area(1.2 * wc), std::numbers::pi * summit_radius * 1.2 * wc, 1e-12 * summit_radius * wc);
  const double e_y = a.yield_strength() / a.effective_modulus();
  const double b = 0.14 * std::exp(23.0 * e_y);
  for (double w : {1.9, 3.0, 10.0, 60.0}) {
    const double a_over_r = std::numbers::pi * a.c_factor() * e_y / 2.0 * std::sqrt(w) * std::pow(w / 1.9, b / 2.0);
    const double radius = std::sqrt(a.contact_area(w * wc) / std::numbers::pi);
    EXPECT_NEAR(radius / summit_radius, a_over_r, 1e-12 * a_over_r) << w;
  }
  EXPECT_EQ(a.contact_area(0.0), 0.0);
}
