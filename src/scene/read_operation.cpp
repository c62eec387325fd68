// How the bearing is run: its oil (lubricant), load, speed and surroundings
// (operating), and its boundary friction law (friction). docs/physics.md sections 2, 5, 6.
#include <fmt/format.h>

#include "scene_names.h"
#include "physical_bounds.h"
#include "scene_sections.h"

namespace twb::scene_io {
namespace {

void read_lubricant(const MapReader& scene, Scene& out) {
  const MapReader oil = scene.map("lubricant", {"conductivity", "viscosity", "max_temperature", "flash_temperature"});
  Lubricant& l = out.lubricant;
  l.conductivity = oil.quantity("conductivity", si::conductivity, bounds::oil_conductivity, l.conductivity);
  l.max_temperature = oil.quantity("max_temperature", si::temperature, bounds::absolute_temperature, l.max_temperature);
  l.flash_temperature =
      oil.quantity("flash_temperature", si::temperature, bounds::absolute_temperature, l.flash_temperature);

  const MapReader viscosity = oil.map("viscosity", {"model", "mu_infinity", "G0", "S0", "value"});
  l.viscosity_model = read_choice(viscosity, "model", kViscosityModels, l.viscosity_model);
  if (l.viscosity_model == ViscosityModel::roelands) {
    viscosity.restrict_to({"model", "mu_infinity", "G0", "S0"}, "with model: roelands");
    l.mu_infinity = viscosity.quantity("mu_infinity", si::viscosity, bounds::mu_infinity, l.mu_infinity);
    l.g0 = viscosity.quantity("G0", si::dimensionless, bounds::roelands_g0, l.g0);
    l.s0 = viscosity.quantity("S0", si::dimensionless, bounds::roelands_s0, l.s0);
  } else {
    viscosity.restrict_to({"model", "value"}, "with model: constant");
    l.constant_viscosity = viscosity.quantity("value", si::viscosity, bounds::constant_viscosity, l.constant_viscosity);
  }
}

void read_operating(const MapReader& scene, Scene& out) {
  const MapReader operating(scene.get("operating", "a map with load, speed, sliding, ambient"),
                            {"load", "speed", "sliding", "ambient"});
  Operating& o = out.operating;
  o.load = operating.quantity("load", si::force, bounds::load);
  o.speed = operating.quantity("speed", si::angular_speed, bounds::speed);
  o.sliding = read_choice(operating, "sliding", kSlidingFilms, o.sliding);
  const Range ambient_range = out.lubricant.viscosity_model == ViscosityModel::roelands
                                  ? bounds::roelands_temperature
                                  : bounds::absolute_temperature;
  o.ambient = operating.quantity("ambient", si::temperature, ambient_range, o.ambient);
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
  read_operating(scene, out);
  read_friction(scene, out);
}

}  // namespace twb::scene_io
