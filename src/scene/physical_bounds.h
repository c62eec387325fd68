// The values a bearing can have: every number a scene gives is checked against these,
// so that a value no thrust washer, oil or operating point can have is an input error
// with its location instead of a solve that ends in overflow (docs/scenes.md, "Bounds").
// Each range is wide: it excludes the impossible, not the unusual; the extremes the
// stability suite solves (tests/stability) lie inside.
#pragma once

#include "scene_node.h"
#include "scene_sections.h"

namespace twb::scene_io::bounds {

// Operating point.
inline constexpr Range load{.low = 0.0, .low_open = true, .high = 1e6,
                            .reason = "a bearing without load has no steady state; at most 1 MN"};
inline constexpr Range speed{.low = 0.0, .high = 1e5,
                             .reason = "at most 1e5 rad/s: kilometres per second of sliding at the washer's rim"};
inline constexpr double kHighestTemperature = 573.15;  // K, 300 degC: above, every mineral or ester oil decomposes
inline constexpr Range roelands_temperature{.low = kRoelandsLowestTemperature, .low_open = true,
                                            .high = kHighestTemperature,
                                            .reason = "Roelands' law needs T > -135 degC; no oil works above 300 degC"};
inline constexpr Range absolute_temperature{.low = 0.0, .low_open = true, .high = kHighestTemperature,
                                            .reason = "an absolute temperature up to 300 degC, where oils decompose"};
// A washer's PV limit: data sheets give 0.1 (unfilled polymers) to about 10 MPa m/s
// (sintered bronzes, filled PTFE); a thousand times either way is no material.
inline constexpr Range pv_limit{.low = 1e2, .high = 1e10, .reason = "a data sheet's PV limit, e.g. 1.8 MPa m/s"};
inline constexpr Range material_temperature{.low = 0.0, .low_open = true, .high = 2000.0,
                                            .reason = "a material's working limit, an absolute temperature up to "
                                                      "2000 K"};
inline constexpr Range film_ratio{.low = 0.0, .high = 100.0,
                                  .reason = "a least h_min/sigma, e.g. 1 (mixed lubrication) or 3 (full film)"};
inline constexpr Range supply_pressure{.low = 0.0, .high = 1e8,
                                       .reason = "a gauge supply pressure up to 1000 bar (transmissions: 1 to 20 bar)"};
inline constexpr Range friction_coefficient{.low = 0.0, .high = 5.0,
                                            .reason = "a dry friction coefficient, 0 to 5"};

// Geometry.
// The film's gap is the tilted plane's small-angle form, c + γ·x (docs/physics.md section
// 1); the plane's own is c + tan γ·x, whose slope differs by γ²/3 relatively: up to
// 50 mrad within 0.1 %, beyond it a model error that grows as γ².
inline constexpr Range tilt{.low = 0.0, .high = 0.05,
                            .reason = "a small imposed tilt of the gear, at most 50 mrad (2.9 degrees), where the "
                                      "model's small-angle gap is within 0.1 % of the tilted plane's"};
inline constexpr Range diameter{.low = 1e-3, .high = 2.0, .reason = "a thrust washer's diameter, 1 mm to 2 m"};
// The gear's free axial travel to its stop (docs/physics.md section 19).
inline constexpr Range axial_play{.low = 0.0, .low_open = true, .high = 1e-2,
                                  .reason = "the gear's free axial travel to its stop, above 0 and at most 10 mm"};
inline constexpr Range thickness{.low = 1e-5, .high = 0.2, .reason = "a thickness from 10 um to 200 mm"};

// Solids.
inline constexpr Range youngs_modulus{.low = 1e8, .high = 1.2e12,
                                      .reason = "from soft polymers (0.1 GPa) to diamond (1200 GPa)"};
inline constexpr Range yield_strength{.low = 1e6, .high = 1e10, .reason = "1 MPa to 10 GPa"};
inline constexpr Range solid_conductivity{.low = 0.01, .high = 2500.0,
                                          .reason = "from foams (0.01 W/m/K) to diamond (2500 W/m/K)"};
inline constexpr Range density{.low = 100.0, .high = 25000.0,
                               .reason = "from foams (100 kg/m^3) to osmium (22600 kg/m^3)"};
inline constexpr Range specific_heat{.low = 50.0, .high = 5000.0, .reason = "50 to 5000 J/kg/K"};
inline constexpr Range thermal_expansion{.low = 0.0, .high = 3e-4,
                                         .reason = "0 (none) to 3e-4 1/K (steels 1.2e-5, polymers to 2e-4)"};

// Surfaces.
inline constexpr Range roughness{.low = 1e-9, .high = 1e-4,
                                 .reason = "from polished (1 nm) to rough-turned (100 um) surfaces"};
inline constexpr Range summit_radius{.low = 1e-8, .high = 1e-2, .reason = "10 nm to 10 mm"};
inline constexpr Range summit_density{.low = 1e6, .high = 1e16, .reason = "1e6 to 1e16 summits per m^2"};
// Archard's specific wear rate k = K/H (docs/physics.md section 20): lubricated steel and
// bronze pairs lie about 1e-19 to 1e-15 m³/(N·m); outside 1e-21 to 1e-9 is a unit slip, not
// a material. 0 is allowed: a face that does not wear.
inline constexpr double kLeastWearRate = 1e-21;
inline constexpr Range wear_rate{.low = 0.0, .high = 1e-9,
                                 .reason = "0 (no wear) or a specific wear rate from 1e-21 to 1e-9 m^3/(N m), "
                                           "e.g. 1e-16 m^3/(N m)"};
inline constexpr Range eta_r_sigma{.low = 1e-4, .high = 10.0,
                                   .reason = "eta R sigma of real surfaces is 0.01 to 0.1; 1e-4 to 10 allowed"};

// Oil.
inline constexpr Range oil_conductivity{.low = 0.01, .high = 1.0, .reason = "oils conduct about 0.13 W/m/K"};
inline constexpr Range mu_infinity{.low = 1e-7, .high = 1e-2, .reason = "Roelands' mu_inf, about 6.3e-5 Pa s"};
inline constexpr Range roelands_g0{.low = 0.0, .low_open = true, .high = 50.0, .reason = "Roelands' G0, about 1 to 10"};
inline constexpr Range roelands_s0{.low = 0.0, .low_open = true, .high = 5.0, .reason = "Roelands' S0, about 1"};
inline constexpr Range constant_viscosity{.low = 1e-6, .high = 1e3,
                                          .reason = "from gases (1e-5 Pa s) to bitumen-like fluids (1e3 Pa s)"};
inline constexpr Range kinematic_viscosity{.low = 1e-7, .high = 1e-1,
                                           .reason = "an oil's kinematic viscosity, 0.1 to 1e5 cSt"};
inline constexpr double kLowestSupplyTemperature = 233.15;  // K, -40 degC: about an ATF's pour point
inline constexpr Range oil_specific_heat{.low = 1000.0, .high = 4000.0,
                                         .reason = "an oil's specific heat, 1000 to 4000 J/(kg K) (ATFs: about 2000)"};
inline constexpr Range oil_density{.low = 500.0, .high = 2000.0, .reason = "an oil's density, 500 to 2000 kg/m^3"};
inline constexpr Range oil_expansion{.low = 0.0, .high = 2e-3,
                                     .reason = "an oil's volumetric expansion, about 6.5e-4 1/K"};
inline constexpr Range viscosity_scale{.low = 0.0, .low_open = true, .high = 1e4,
                                       .reason = "a factor on the oil's viscosity, e.g. 0.5 for half as viscous"};

// The washer's grooves (read_grooves.cpp).
inline constexpr Range dam_radius{.low = 0.0, .low_open = true, .high = 1.0,
                                  .reason = "a radius on the washer's face (its film's radii are checked once the grooves are placed)"};
inline constexpr Range groove_depth{.low = 1e-7, .high = 5e-3,
                                    .reason = "a groove from 0.1 um to 5 mm deep (thrust washers: 10 to 100 um)"};

// Numerics.
inline constexpr Range tolerance{.low = 0.0, .low_open = true, .high = 1e-2,
                                 .reason = "a scaled residual or step, 1e-2 at the loosest"};
// IDA's relative tolerance of a duty cycle's march: 1e-4 still moves a ten-minute cycle's
// end state by only 3.5e-5 K (benchmarks/README.md); below 1e-10 the error test asks for
// more than the state's rounding holds.
inline constexpr Range march_tolerance{.low = 1e-10, .high = 1e-3,
                                       .reason = "a relative tolerance from 1e-10 to 1e-3 (default 1e-6)"};
inline constexpr Range cold_start_film{.low = 0.0, .low_open = true, .high = 1e3,
                                       .reason = "h_min/sigma of the cold start, e.g. 3"};
inline constexpr Range duration{.low = 0.0, .high = 1e7, .reason = "at most 1e7 s of pseudo-time"};
// A life study (docs/physics.md section 20): a washer's life in slow time, up to a
// century; its depths to a tolerance between an atom's size and a millimetre.
inline constexpr Range life_duration{.low = 0.0, .low_open = true, .high = 3.2e9,
                                     .reason = "a life above 0 and at most a century, e.g. 2000 h"};
inline constexpr Range depth_tolerance{.low = 1e-10, .high = 1e-3,
                                       .reason = "an absolute depth from 0.1 nm to 1 mm, e.g. 0.01 um"};
inline constexpr int kMostRadialNodes = 1025, kMostCircumferentialNodes = 8192, kMostQuadraturePoints = 32;
inline constexpr int kMostIterations = 100000;

}  // namespace twb::scene_io::bounds
