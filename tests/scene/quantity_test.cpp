// Unit conversions at load time must be exact scalings (or offsets, for temperatures):
// the model never sees anything but SI.
#include "scene/quantity.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace twb {
namespace {

void expect_relative(double actual, double expected) {
  EXPECT_NEAR(actual, expected, 1e-12 * std::abs(expected)) << "expected " << expected;
}

TEST(Quantity, RevolutionsPerMinuteAreTwoPiRadiansPerMinute) {
  expect_relative(to_si("5200 rpm", si::angular_speed), 5200.0 * 2.0 * std::numbers::pi / 60.0);
}

TEST(Quantity, RadiansPerSecondAndPerSecondAreTheSameAngularSpeed) {
  EXPECT_EQ(to_si("545 rad/s", si::angular_speed), 545.0);
  EXPECT_EQ(to_si("545 1/s", si::angular_speed), 545.0);
}

TEST(Quantity, CelsiusConvertsToKelvinWithItsOffset) {
  expect_relative(to_si("24 degC", si::temperature), 297.15);
  expect_relative(to_si("24 °C", si::temperature), 297.15);
  expect_relative(to_si("-135 degC", si::temperature), 138.15);
}

TEST(Quantity, BareNumbersAreSi) {
  EXPECT_EQ(to_si("297.15", si::temperature), 297.15);
  EXPECT_EQ(to_si("0.0227", si::length), 0.0227);
  EXPECT_EQ(to_si("1e-10", si::dimensionless), 1e-10);
  EXPECT_EQ(to_si("+5", si::force), 5.0);
}

TEST(Quantity, MilliradiansAreAnAngleAndSoIsAPlainNumber) {
  expect_relative(to_si("2 mrad", si::angle), 0.002);
  expect_relative(to_si("0.002", si::angle), 0.002);
}

TEST(Quantity, LengthsWithPrefixes) {
  expect_relative(to_si("22.7 mm", si::length), 0.0227);
  expect_relative(to_si("0.45 um", si::length), 0.45e-6);
  expect_relative(to_si("0.515 µm", si::length), 0.515e-6);
}

TEST(Quantity, MaterialAndOilProperties) {
  expect_relative(to_si("201 GPa", si::stress), 201e9);
  expect_relative(to_si("0.993 GPa", si::stress), 0.993e9);
  expect_relative(to_si("0.145 W/(m K)", si::conductivity), 0.145);
  expect_relative(to_si("60.5 W/(m degC)", si::conductivity), 60.5);
  expect_relative(to_si("7850 kg/m^3", si::density), 7850.0);
  expect_relative(to_si("7.85 g/cm^3", si::density), 7850.0);
  expect_relative(to_si("470 J/(kg K)", si::specific_heat), 470.0);
  expect_relative(to_si("0.06 Pa s", si::viscosity), 0.06);
  expect_relative(to_si("60 mPa s", si::viscosity), 0.06);
  expect_relative(to_si("6.31e-5 Pa s", si::viscosity), 6.31e-5);
  expect_relative(to_si("1000 N", si::force), 1000.0);
  expect_relative(to_si("1.2 kN", si::force), 1200.0);
}

std::string error_of(std::string_view text, const SiUnit& unit) {
  try {
    to_si(text, unit);
  } catch (const QuantityError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(Quantity, WrongDimensionNamesBothDimensions) {
  EXPECT_EQ(error_of("22.7 mm", si::angular_speed),
            "'22.7 mm' has the dimension of length, expected an angular speed convertible to rad/s");
  EXPECT_EQ(error_of("2 mrad", si::force),
            "'2 mrad' is dimensionless, expected a force convertible to N");
}

// udunits2 would convert reciprocal units into each other; a scene must not.
TEST(Quantity, ReciprocalUnitsAreNotConvertible) {
  EXPECT_EQ(error_of("10 s", si::angular_speed),
            "'10 s' has the dimension of time, expected an angular speed convertible to rad/s");
  EXPECT_NE(error_of("2 m^2", si::areal_density).find("has the dimension of area"), std::string::npos);
}

TEST(Quantity, UnknownUnitIsNamed) {
  EXPECT_NE(error_of("1000 Nx", si::force).find("unknown unit 'Nx'"), std::string::npos);
}

// Spellings people type: centipoise and "deg" are accepted as what they mean; a bare
// C or F for a temperature, a kinematic viscosity and "RPM" get a hint.
TEST(Quantity, CommonSpellingsAreAcceptedOrGetAHint) {
  EXPECT_DOUBLE_EQ(to_si("30 cP", si::viscosity), 0.03);
  EXPECT_DOUBLE_EQ(to_si("30 mPa s", si::viscosity), to_si("30 cP", si::viscosity));
  EXPECT_DOUBLE_EQ(to_si("0.1 deg", si::angle), 0.1 * std::numbers::pi / 180);
  EXPECT_EQ(error_of("80 C", si::temperature),
            "'80 C' has units 'C' (did you mean 'degC'? 'C' is the coulomb), expected a temperature convertible to K");
  EXPECT_NE(error_of("80 F", si::temperature).find("did you mean 'degF'?"), std::string::npos);
  EXPECT_NE(error_of("30 cSt", si::viscosity).find("a kinematic viscosity"), std::string::npos);
  EXPECT_NE(error_of("5000 RPM", si::angular_speed).find("unknown unit 'RPM' (write 'rpm')"), std::string::npos);
  // A coulomb where a charge could be meant is not second-guessed.
  EXPECT_EQ(error_of("80 C", si::force).find("did you mean"), std::string::npos);
}

TEST(Quantity, UnparseableAndNonFiniteNumbersAreRejected) {
  EXPECT_NE(error_of("1O00 N", si::force).find("'1O00 N' is not a number"), std::string::npos);
  EXPECT_NE(error_of("22.7mm", si::length).find("is not a number"), std::string::npos);
  EXPECT_NE(error_of("nan", si::force).find("not a finite number"), std::string::npos);
  EXPECT_NE(error_of(".inf N", si::force).find("not a finite number"), std::string::npos);
  EXPECT_NE(error_of("1e999 N", si::force).find("not a finite number"), std::string::npos);
}

TEST(Quantity, DimensionNames) {
  EXPECT_EQ(dimension_name("mm"), "length");
  EXPECT_EQ(dimension_name("GPa"), "pressure");
  EXPECT_EQ(dimension_name("rpm"), "angular speed (or frequency)");
  EXPECT_EQ(dimension_name("no_such_unit"), "");
}

}  // namespace
}  // namespace twb
