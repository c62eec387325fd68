// How the bearing is run: its oil (lubricant), load, speed and surroundings
// (operating), and its boundary friction law (friction). docs/physics.md sections 2, 5, 6.
#include <array>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "scene_names.h"
#include "physical_bounds.h"
#include "scene_sections.h"
#include "physics/viscosity_fit.h"

namespace twb::scene_io {
namespace {

// The oil's density at temperature t (K), from the data sheet's value at its reference
// temperature and a volumetric expansion (docs/physics.md section 5).
struct OilDensity {
  double value = 0, reference = 0, expansion = 0;
  double at(double t) const { return value * (1.0 - expansion * (t - reference)); }
};

OilDensity read_density(const MapReader& viscosity, bool required, std::string_view why) {
  OilDensity d;
  if (!viscosity.has("density")) {
    if (required)
      viscosity.node().fail(fmt::format("{}: needs density (kg/m^3, e.g. 850 kg/m^3) {}", viscosity.node().name(), why));
    return d;
  }
  d.value = viscosity.quantity("density", si::density, bounds::oil_density);
  d.reference = viscosity.quantity("density_temperature", si::temperature, bounds::absolute_temperature, 288.15);
  d.expansion = viscosity.quantity("density_expansion", si::expansion, bounds::oil_expansion, 6.5e-4);
  return d;
}

// The density the oil carries its heat with (convection) is the data sheet's, at 15 degC.
void take_density(const OilDensity& d, Lubricant& l) {
  l.density = d.at(288.15);
  l.density_expansion = d.expansion * d.value / l.density;
}

void read_fitted_viscosity(const MapReader& viscosity, bool data_sheet, Lubricant& l) {
  ViscosityFit fit;
  if (data_sheet) {
    viscosity.restrict_to({"model", "kv40", "kv100", "density", "density_temperature", "density_expansion"},
                          "with model: data_sheet");
    const double nu40 = viscosity.quantity("kv40", si::kinematic_viscosity, bounds::kinematic_viscosity);
    const double nu100 = viscosity.quantity("kv100", si::kinematic_viscosity, bounds::kinematic_viscosity);
    if (nu100 >= nu40) {
      const Node node = viscosity.get("kv100", "");
      node.fail(fmt::format("{}: {} at 100 degC is not below kv40 {} at 40 degC; an oil thins as it warms: give "
                            "the data sheet's kinematic viscosity at 100 degC, less than at 40 degC",
                            node.path(), node.yaml().Scalar(), viscosity.get("kv40", "").yaml().Scalar()));
    }
    const OilDensity d = read_density(viscosity, true, "to turn the kinematic viscosities into dynamic ones");
    fit = fit_data_sheet(nu40, nu100, d.value, d.reference, d.expansion);
    take_density(d, l);
  } else {
    viscosity.restrict_to({"model", "points", "density", "density_temperature", "density_expansion"},
                          "with model: table");
    const Node table = viscosity.get("points", "a list of {temperature, viscosity} or {temperature, kinematic}");
    const std::vector<Node> rows =
        table.list("a list of points, each {temperature: 40 degC, viscosity: 0.025 Pa s} or "
                   "{temperature: 40 degC, kinematic: 29.5 cSt}");
    if (rows.size() < 2)
      table.fail(fmt::format("{}: {} point{}; a viscosity table needs at least two (two fix Roelands' G0 and "
                             "S0, three or more fit mu_infinity too)",
                             table.path(), rows.size(), rows.size() == 1 ? "" : "s"));
    const OilDensity d = read_density(viscosity, false, "");
    if (d.value > 0) take_density(d, l);
    std::vector<ViscosityPoint> points;
    std::vector<double> kinematic;
    for (const Node& row : rows) {
      const MapReader p(row, {"temperature", "viscosity", "kinematic"});
      // Roelands' law is fitted on 1 + T_C/135, which must be positive.
      const double t = p.quantity("temperature", si::temperature, bounds::roelands_temperature);
      double mu = 0;
      if (p.has("kinematic")) {
        p.restrict_to({"temperature", "kinematic"}, "with kinematic");
        if (d.value <= 0)
          viscosity.node().fail(fmt::format("{}: a kinematic viscosity in points needs the oil's density "
                                            "(density: 850 kg/m^3)",
                                            viscosity.node().name()));
        const double nu = p.quantity("kinematic", si::kinematic_viscosity, bounds::kinematic_viscosity);
        kinematic.push_back(nu);
        mu = d.at(t) * nu;
      } else {
        mu = p.quantity("viscosity", si::viscosity, bounds::constant_viscosity);
      }
      if (!points.empty() && !(t > points.back().temperature && mu < points.back().viscosity))
        row.fail(fmt::format("{}: the points must rise in temperature and fall in viscosity ({} after {:.2f} degC, "
                             "{:.4g} Pa s)",
                             row.path(), mu < points.back().viscosity ? "a temperature not above" : "a viscosity not below",
                             points.back().temperature - 273.15, points.back().viscosity));
      points.push_back({t, mu});
    }
    // Two points fix G0 and S0 with Roelands' own μ∞ (6.31e-5 Pa s); more are fitted.
    try {
      fit = points.size() == 2 ? fit_roelands(points, 6.31e-5) : fit_roelands(points);
    } catch (const std::invalid_argument& e) {
      // Points no Roelands law passes through (two below its mu_infinity of 6.31e-5 Pa s).
      table.fail(fmt::format("{}: Roelands' law cannot be fitted to these points: {}; check their values and units",
                             table.path(), e.what()));
    }

  }
  // The fitted law must be one the scene accepts as given (it is described so, and loads
  // back): a fit outside Roelands' ranges means points no oil follows (units, a typo).
  const struct {
    const char* name;
    double value;
    const Range& range;
  } fitted[] = {{"mu_infinity", fit.law.mu_infinity, bounds::mu_infinity},
                {"G0", fit.law.g0, bounds::roelands_g0},
                {"S0", fit.law.s0, bounds::roelands_s0}};
  for (const auto& f : fitted)
    if (!f.range.contains(f.value))
      viscosity.node().fail(fmt::format("{}: the {} fit Roelands' law only with {} = {:.4g}, which must be {} ({}); no "
                                        "oil follows such points: check their values and units",
                                        viscosity.node().path(), data_sheet ? "data sheet's viscosities" : "points",
                                        f.name, f.value, f.range.describe(), f.range.reason));
  l.mu_infinity = fit.law.mu_infinity;
  l.g0 = fit.law.g0;
  l.s0 = fit.law.s0;
  ViscositySource src{data_sheet ? "data_sheet" : "table", {}, {}, fit.relative_errors, fit.largest_error};
  for (const ViscosityPoint& p : fit.points) {
    src.temperatures.push_back(p.temperature);
    src.viscosities.push_back(p.viscosity);
  }
  l.viscosity_source = std::move(src);
}

void read_lubricant(const MapReader& scene, Scene& out) {
  const MapReader oil = scene.map("lubricant", {std::begin(kLubricantKeys), std::end(kLubricantKeys)});
  Lubricant& l = out.lubricant;
  l.conductivity = oil.quantity("conductivity", si::conductivity, bounds::oil_conductivity, l.conductivity);
  l.max_temperature = oil.quantity("max_temperature", si::temperature, bounds::absolute_temperature, l.max_temperature);
  l.flash_temperature =
      oil.quantity("flash_temperature", si::temperature, bounds::absolute_temperature, l.flash_temperature);
  if (oil.has("supply")) {
    // Whether the grooves it feeds exist is checked with the grooves (read_grooves.cpp).
    const MapReader supply = oil.map("supply", {std::begin(kSupplyKeys), std::end(kSupplyKeys)});
    l.supply = OilSupply{supply.quantity("pressure", si::stress, bounds::supply_pressure),
                         read_choice(supply, "at", kSupplyInlets, SupplyInlet::inner_radius)};
    if (supply.has("temperature")) {
      // From an ATF's pour point to below the oil's own flash point.
      const Range fed{.low = bounds::kLowestSupplyTemperature, .high = l.flash_temperature, .high_open = true,
                      .reason = "oil fed between an ATF's pour point (-40 degC) and the oil's flash point "
                                "(lubricant.flash_temperature)"};
      l.supply->temperature = supply.quantity("temperature", si::temperature, fed);
    }
    l.supply->carry_over = supply.quantity("carry_over", si::dimensionless,
                                           Range{.low = 0.0, .high = 1.0, .high_open = true,
                                                 .reason = "a share of the hot oil, from 0 up to (not) 1"},
                                           l.supply->carry_over);
  }
  l.specific_heat = oil.quantity("specific_heat", si::specific_heat, bounds::oil_specific_heat, l.specific_heat);

  const MapReader viscosity =
      oil.map("viscosity", {"model", "mu_infinity", "G0", "S0", "value", "kv40", "kv100", "density",
                            "density_temperature", "density_expansion", "points"});
  // data_sheet and table are Roelands' law fitted at load time (physics/viscosity_fit.h).
  static constexpr std::string_view kModels[] = {"roelands", "constant", "data_sheet", "table"};
  const std::size_t model = viscosity.choice("model", kModels, 0);
  l.viscosity_model = model == 1 ? ViscosityModel::constant : ViscosityModel::roelands;
  if (model >= 2) {
    read_fitted_viscosity(viscosity, model == 2, l);
  } else if (l.viscosity_model == ViscosityModel::roelands) {
    viscosity.restrict_to({"model", "mu_infinity", "G0", "S0"}, "with model: roelands");
    l.mu_infinity = viscosity.quantity("mu_infinity", si::viscosity, bounds::mu_infinity, l.mu_infinity);
    l.g0 = viscosity.quantity("G0", si::dimensionless, bounds::roelands_g0, l.g0);
    l.s0 = viscosity.quantity("S0", si::dimensionless, bounds::roelands_s0, l.s0);
  } else {
    viscosity.restrict_to({"model", "value"}, "with model: constant");
    l.constant_viscosity = viscosity.quantity("value", si::viscosity, bounds::constant_viscosity, l.constant_viscosity);
  }
  l.density = oil.quantity("density", si::density, bounds::oil_density, l.density);
  l.density_expansion = oil.quantity("density_expansion", si::expansion, bounds::oil_expansion, l.density_expansion);
}

void read_operating(const MapReader& scene, Scene& out) {
  const MapReader operating(scene.get("operating", "a map with load, speed, sliding, ambient"),
                            {std::begin(kOperatingKeys), std::end(kOperatingKeys)});
  Operating& o = out.operating;
  o.load = operating.quantity("load", si::force, bounds::load);
  o.speed = operating.quantity("speed", si::angular_speed, bounds::speed);
  o.sliding = read_choice(operating, "sliding", kSlidingFilms, o.sliding);
  const Range ambient_range = out.lubricant.viscosity_model == ViscosityModel::roelands
                                  ? bounds::roelands_temperature
                                  : bounds::absolute_temperature;
  o.ambient = operating.quantity("ambient", si::temperature, ambient_range, o.ambient);
}

// limits: failure criteria besides the temperatures of the oil and the materials.
void read_limits(const MapReader& scene, Scene& out) {
  const MapReader limits = scene.map("limits", {"min_film_ratio", "scuffing_temperature", "wear_depth"});
  if (limits.has("min_film_ratio"))
    out.limits.min_film_ratio = limits.quantity("min_film_ratio", si::dimensionless, bounds::film_ratio);
  out.limits.scuffing_temperature = limits.quantity("scuffing_temperature", si::temperature,
                                                    bounds::absolute_temperature, out.limits.scuffing_temperature);
  if (!limits.has("wear_depth")) return;
  const Node allowance = limits.get("wear_depth", "");
  if (!out.effects.wear)
    allowance.fail(fmt::format("{}: a wear allowance needs the effect 'wear' (without it no face wears); add wear "
                               "to 'effects' or leave the allowance out",
                               allowance.path()));
  // Depths far below the washer's thickness, which the model takes as unchanged
  // (docs/physics.md section 20).
  const std::string reason =
      fmt::format("a depth above 0 and at most the washer's thickness, {:.4g} mm", 1e3 * out.washer.thickness);
  out.limits.wear_depth = limits.quantity(
      "wear_depth", si::length, Range{.low = 0.0, .low_open = true, .high = out.washer.thickness, .reason = reason});
}

// With `wear` on, both faces of the sliding film need Archard's k (docs/physics.md section
// 20): twb ships no default, the rate belongs to the pair.
void check_wear_rates(const MapReader& scene, const Scene& out) {
  if (!out.effects.wear) return;
  const bool carrier_slides = out.operating.sliding == SlidingFilm::carrier_washer;
  const std::array<std::pair<std::string_view, const Component*>, 2> faces{
      carrier_slides ? std::pair{std::string_view("carrier"), &out.carrier} : std::pair{std::string_view("washer"), &out.washer},
      carrier_slides ? std::pair{std::string_view("washer"), &out.washer} : std::pair{std::string_view("gear"), &out.gear}};
  // A face that does not slide does not wear, and so does not run in.
  for (const auto& [name, component] :
       {std::pair{std::string_view("carrier"), &out.carrier}, std::pair{std::string_view("gear"), &out.gear}}) {
    if (!component->roughness.run_in_rq || faces[0].second == component || faces[1].second == component) continue;
    const MapReader surfaces = scene.map("surfaces", {"carrier", "washer", "gear", "asperities"});
    const Node where = surfaces.map(name, {"Ra", "Rq", "wear_rate", "run_in_rq"}).get("run_in_rq", "");
    where.fail(fmt::format("{}: the {}'s face is not on the sliding film ({}): it does not wear, and so does not run "
                           "in; leave run_in_rq out",
                           where.path(), name, kSlidingFilms.name(out.operating.sliding)));
  }
  for (const auto& [name, component] : faces) {
    if (component->roughness.wear_rate) continue;
    const MapReader surfaces = scene.map("surfaces", {"carrier", "washer", "gear", "asperities"});
    const Node where = surfaces.has(name) ? surfaces.get(name, "") : surfaces.node();
    where.fail(fmt::format("{}: with the effect 'wear' each face of the sliding film ({}) needs its specific wear "
                           "rate, and surfaces.{} has none: add e.g. 'wear_rate: 1e-16 m^3/(N m)' (0: the face "
                           "does not wear; docs/physics.md section 20)",
                           where.path(), kSlidingFilms.name(out.operating.sliding), name));
  }
}


void read_friction(const MapReader& scene, Scene& out) {
  const MapReader friction = scene.map("friction", {"law", "coefficient"});
  Friction& f = out.friction;
  f.law = read_choice(friction, "law", kFrictionLaws, f.law);
  if (f.law == FrictionLaw::constant) {
    f.coefficient = friction.quantity("coefficient", si::dimensionless, bounds::friction_coefficient, f.coefficient);
  } else {
    friction.restrict_to({"law"}, "with law: empirical");
  }
}

}  // namespace

void read_operation(const MapReader& scene, Scene& out) {
  read_lubricant(scene, out);
  read_limits(scene, out);
  read_operating(scene, out);
  read_friction(scene, out);
  check_wear_rates(scene, out);
}

}  // namespace twb::scene_io
