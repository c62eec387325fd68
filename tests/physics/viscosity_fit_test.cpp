// The oil from its data sheet (docs/physics.md section 5): Walther through the two points,
// Roelands fitted to it, the given viscosities reproduced.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/viscosity_fit.h"

namespace twb {
namespace {

constexpr double kCelsius = 273.15;

// Walther's relation is two-parameter: through its two points exactly (to rounding of the
// double logarithm, ~1e-12 relative).
TEST(ViscosityFit, WaltherPassesThroughItsPoints) {
  const double t1 = kCelsius + 40, t2 = kCelsius + 100;
  EXPECT_NEAR(walther_viscosity(t1, 29.5e-6, t2, 6.0e-6, t1) / 29.5e-6, 1.0, 1e-12);
  EXPECT_NEAR(walther_viscosity(t1, 29.5e-6, t2, 6.0e-6, t2) / 6.0e-6, 1.0, 1e-12);
  // Falling in temperature between and beyond them.
  double previous = INFINITY;
  for (double t = kCelsius; t < kCelsius + 200; t += 10) {
    const double nu = walther_viscosity(t1, 29.5e-6, t2, 6.0e-6, t);
    EXPECT_LT(nu, previous);
    previous = nu;
  }
}

// The ATF and typical ISO VG 32 / VG 68 hydraulic-oil data sheets (kinematic
// viscosity at 40 and 100 degC, density at 15 degC): the bound is 1 % at the
// given points. Roelands follows Walther over 20-160 degC to about 0.5 % (its three
// constants against Walther's two), so the points are met well within it.
struct Sheet {
  const char* name;
  double nu40, nu100, density;
};
class DataSheets : public ::testing::TestWithParam<Sheet> {};
TEST_P(DataSheets, ReproduceTheGivenViscosities) {
  const Sheet s = GetParam();
  const ViscosityFit fit = fit_data_sheet(s.nu40 * 1e-6, s.nu100 * 1e-6, s.density, kCelsius + 15, 6.5e-4);
  ASSERT_EQ(fit.points.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const double t = fit.points[k].temperature;
    const double rho = s.density * (1 - 6.5e-4 * (t - kCelsius - 15));
    const double given = rho * (k == 0 ? s.nu40 : s.nu100) * 1e-6;
    EXPECT_NEAR(fit.law(t).value / given, 1.0, 0.01) << s.name << " at " << t - kCelsius << " degC";
    EXPECT_NEAR(fit.relative_errors[k], fit.law(t).value / given - 1.0, 1e-12);
  }
  EXPECT_LT(fit.largest_error, 0.01) << s.name;
}
INSTANTIATE_TEST_SUITE_P(Oils, DataSheets,
                         ::testing::Values(Sheet{"ATF", 29.5, 6.0, 850}, Sheet{"ISO VG 32", 32.0, 5.4, 872},
                                           Sheet{"ISO VG 68", 68.0, 8.6, 886}));

// Points taken from a known Roelands law are fitted back to it: the fit's minimum is that
// law (residual zero), found by Brent to its tolerance (relative ~1e-6 in mu_infinity).
TEST(ViscosityFit, RecoversTheLawItWasSampledFrom) {
  const RoelandsViscosity paper{6.31e-5, 3.545, 1.053};
  std::vector<ViscosityPoint> points;
  for (double c : {20.0, 40.0, 70.0, 100.0, 130.0}) points.push_back({kCelsius + c, paper(kCelsius + c).value});
  const ViscosityFit fit = fit_roelands(points);
  EXPECT_NEAR(fit.law.mu_infinity / paper.mu_infinity, 1.0, 1e-4);
  EXPECT_NEAR(fit.law.g0 / paper.g0, 1.0, 1e-4);
  EXPECT_NEAR(fit.law.s0 / paper.s0, 1.0, 1e-4);
  EXPECT_LT(fit.largest_error, 1e-6);
}

// Two points with Roelands' mu_infinity: G0 and S0 are met exactly.
TEST(ViscosityFit, TwoPointsWithGivenMuInfinityAreMetExactly) {
  const RoelandsViscosity paper{6.31e-5, 3.545, 1.053};
  const std::vector<ViscosityPoint> points{{kCelsius + 40, paper(kCelsius + 40).value},
                                           {kCelsius + 100, paper(kCelsius + 100).value}};
  const ViscosityFit fit = fit_roelands(points, 6.31e-5);
  EXPECT_NEAR(fit.law.g0, paper.g0, 1e-10);
  EXPECT_NEAR(fit.law.s0, paper.s0, 1e-10);
}

}  // namespace
}  // namespace twb
