// Physical quantities written in scene files ("22.7 mm", "5200 rpm", "24 degC"),
// converted once, at load time, to the SI unit the model works in. Units are those
// of udunits2; a bare number is taken to be in SI already.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace twb {

// The SI unit a scene value is converted to, and how to talk about it in messages.
struct SiUnit {
  std::string_view symbol;   // udunits2 spelling of the SI unit, e.g. "rad/s"
  std::string_view kind;     // what the value is, e.g. "an angular speed"
  std::string_view example;  // a valid value, e.g. "545 rad/s"
};

namespace si {
inline constexpr SiUnit length{"m", "a length", "22.7 mm"};
// udunits2 treats the radian as dimensionless: any dimensionless number is an angle.
inline constexpr SiUnit angle{"rad", "an angle", "2 mrad"};
inline constexpr SiUnit angular_speed{"rad/s", "an angular speed", "545 rad/s"};
inline constexpr SiUnit force{"N", "a force", "1000 N"};
inline constexpr SiUnit torque{"N m", "a torque", "0.3 N m"};
inline constexpr SiUnit time{"s", "a time", "60 s"};
inline constexpr SiUnit temperature{"K", "a temperature", "24 degC"};
inline constexpr SiUnit stress{"Pa", "a pressure or stress", "201 GPa"};
inline constexpr SiUnit conductivity{"W/(m K)", "a thermal conductivity", "60.5 W/(m K)"};
inline constexpr SiUnit density{"kg/m^3", "a density", "7850 kg/m^3"};
inline constexpr SiUnit specific_heat{"J/(kg K)", "a specific heat", "470 J/(kg K)"};
inline constexpr SiUnit viscosity{"Pa s", "a dynamic viscosity", "0.06 Pa s"};
inline constexpr SiUnit kinematic_viscosity{"m^2/s", "a kinematic viscosity", "29.5 mm^2/s"};
inline constexpr SiUnit areal_density{"1/m^2", "a number per unit area", "1e11 1/m^2"};
inline constexpr SiUnit expansion{"1/K", "a thermal expansion coefficient", "1.2e-5 1/K"};
inline constexpr SiUnit dimensionless{"1", "a dimensionless number", "0.296"};
inline constexpr SiUnit pv{"Pa m/s", "a PV value (a pressure times a sliding speed)", "1.8 MPa m/s"};
// Archard's specific wear rate: worn volume per unit of load and sliding distance.
inline constexpr SiUnit wear_rate{"m^3/(N m)", "a specific wear rate (worn volume per load and sliding distance)",
                                  "1e-16 m^3/(N m)"};
// Every unit above, the angle before the pure number (udunits2 takes both for "rad").
inline constexpr const SiUnit* all[] = {&length,        &angle,         &angular_speed, &force,         &torque,
                                        &time,          &temperature,   &stress,        &conductivity,
                                        &density,       &specific_heat, &viscosity,     &kinematic_viscosity,
                                        &areal_density, &expansion,     &dimensionless, &pv,
                                        &wear_rate};
// The unit of a symbol above ("rad/s"); the pure number for any other.
inline const SiUnit& of_symbol(std::string_view symbol) {
  for (const SiUnit* u : all)
    if (u->symbol == symbol) return *u;
  return dimensionless;
}
}  // namespace si

// A text that is not a quantity of the expected kind. The message says what was wrong
// and what was expected, but not where: the scene loader adds the location.
class QuantityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "22.7 mm" with si::length -> 0.0227. The text is a number, optionally followed by
// whitespace and a udunits2 unit. Temperatures convert with their offset
// ("24 degC" -> 297.15). Throws QuantityError for an unparseable number, a non-finite
// number, an unknown unit or a unit of the wrong dimension.
double to_si(std::string_view text, const SiUnit& expected);

// The dimension of a udunits2 unit expression, for messages: "length", "a force", ...
// "dimensionless" for pure numbers and angles, empty if unknown or unparseable.
std::string dimension_name(std::string_view unit);

}  // namespace twb
