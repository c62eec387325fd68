// Jackson-Green single asperity, docs/physics.md section 4 / paper eqs [8]-[12].
#include "physics/asperity_contact.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace {

// Table 1 steel on steel.
constexpr double youngs = 201e9, poisson = 0.296, yield = 0.993e9, radius = 20e-6;

twb::JacksonGreenAsperity table1_asperity() {
  return {twb::JacksonGreenAsperity::effective_modulus(youngs, poisson, youngs, poisson),
          yield, poisson, radius};
}

TEST(JacksonGreenAsperity, EffectiveModulusOfIdenticalMaterials) {
  // Identical materials: E' = E / (2 (1 - nu^2)).
  const double expected = youngs / (2.0 * (1.0 - poisson * poisson));
  EXPECT_NEAR(twb::JacksonGreenAsperity::effective_modulus(youngs, poisson, youngs, poisson) /
                  expected, 1.0, 1e-15);
  EXPECT_NEAR(expected, 110150989057.239057, 1e-3);  // mpmath
  // A rigid counterface leaves E/(1 - nu^2).
  EXPECT_NEAR(twb::JacksonGreenAsperity::effective_modulus(youngs, poisson, 1e300, 0.3) /
                  (youngs / (1.0 - poisson * poisson)), 1.0, 1e-15);
}

TEST(JacksonGreenAsperity, CriticalValuesOfTable1Steel) {
  const auto asperity = table1_asperity();
  // Independently (mpmath, 30 digits): C = 1.295 e^(0.736*0.296),
  // omega_c = (pi C S_y/(2E'))^2 R, P_c = (4/3)(R/E')^2 (pi C S_y/2)^3.
  EXPECT_NEAR(asperity.c_factor() / 1.61021336514661060503, 1.0, 1e-15);
  EXPECT_NEAR(asperity.critical_interference() / 1.03982031663887622e-8, 1.0, 1e-14);
  EXPECT_NEAR(asperity.critical_force() / 6.96433387869284949e-4, 1.0, 1e-14);
  // And by hand here: e^(0.217856) = 1.243408...
  const double c = 1.295 * std::exp(0.736 * 0.296);
  const double e_eff = 201e9 / (2 * (1 - 0.296 * 0.296));
  const double ratio = std::numbers::pi * c * 0.993e9 / (2 * e_eff);
  EXPECT_NEAR(asperity.critical_interference() / (ratio * ratio * 20e-6), 1.0, 1e-14);
}

TEST(JacksonGreenAsperity, ElasticBranchIsHertz) {
  // P_c (w/w_c)^1.5 = (4/3)(R/E')^2 (pi C S_y/2)^3 w^1.5 / [(pi C S_y/(2E'))^3 R^1.5]
  //                 = (4/3) E' R^(1/2) w^1.5   (the C S_y factors cancel): Hertz.
  const auto asperity = table1_asperity();
  const double e_eff = asperity.effective_modulus();
  for (double omega_star : {1e-6, 0.01, 0.5, 1.0, 1.5, 1.9}) {
    const double w = omega_star * asperity.critical_interference();
    const double hertz = 4.0 / 3.0 * e_eff * std::sqrt(radius) * std::pow(w, 1.5);
    EXPECT_NEAR(asperity.force(w) / hertz, 1.0, 1e-13) << omega_star;
  }
}

TEST(JacksonGreenAsperity, ElastoPlasticValues) {
  // P/P_c from an independent mpmath implementation of eqs [9], [10] (corrected).
  const auto asperity = table1_asperity();
  const double wc = asperity.critical_interference(), pc = asperity.critical_force();
  EXPECT_NEAR(asperity.force(2.0 * wc) / pc, 2.83140033011394109, 1e-12);
  EXPECT_NEAR(asperity.force(10.0 * wc) / pc, 25.8250066979281541, 1e-11);
  EXPECT_NEAR(asperity.force(100.0 * wc) / pc, 420.501707738773313, 1e-9);
  EXPECT_NEAR(asperity.force(1000.0 * wc) / pc, 3387.18364531341212, 1e-8);
}

TEST(JacksonGreenAsperity, ZeroWithoutInterference) {
  const auto asperity = table1_asperity();
  EXPECT_EQ(asperity.force(0.0), 0.0);
  EXPECT_EQ(asperity.force(-1e-6), 0.0);
}

TEST(JacksonGreenAsperity, MonotoneIncreasing) {
  // The fit [9] starts 0.55 % above [8] at omega* = 1.9 (a jump up), so monotone still.
  const auto asperity = table1_asperity();
  const double wc = asperity.critical_interference();
  double previous = 0.0;
  for (double omega_star = 1e-3; omega_star <= 1000.0; omega_star *= 1.001) {
    const double force = asperity.force(omega_star * wc);
    ASSERT_GT(force, previous) << omega_star;
    previous = force;
  }
  const double at_transition = asperity.force(1.9 * wc);
  const double past_transition = asperity.force(std::nextafter(1.9 * wc, 1.0));
  EXPECT_GT(past_transition, at_transition);
  EXPECT_LT(past_transition / at_transition - 1.0, 0.006);
}

}  // namespace
