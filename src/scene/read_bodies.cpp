// The three solid bodies: their annuli and thicknesses (geometry), their steels
// (materials) and their faces' roughness (surfaces). MODEL.md sections 1, 4 and 10.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "scene_names.h"
#include "physical_bounds.h"
#include "scene_sections.h"

namespace twb::scene_io {
namespace {

// The gear's imposed tilt must stay a small angle for the model's linearised kinematics.

struct Annulus {
  double inner_radius;
  double outer_radius;
};

Annulus read_annulus(const MapReader& body) {
  const double inner = body.quantity("inner_diameter", si::length, bounds::diameter);
  const double outer = body.quantity("outer_diameter", si::length, bounds::diameter);
  if (inner >= outer) {
    const Node node = body.get("inner_diameter", "");
    node.fail(fmt::format("{}: '{}' must be less than outer_diameter '{}'", node.path(),
                          node.yaml().Scalar(), body.get("outer_diameter", "").yaml().Scalar()));
  }
  return {inner / 2.0, outer / 2.0};
}

void read_geometry(const MapReader& scene, Scene& out) {
  const MapReader geometry(scene.get("geometry", "a map with carrier, washer, gear"),
                           {"carrier", "washer", "gear"});
  const MapReader carrier(geometry.get("carrier", "a map with thickness"), {"thickness"});
  const MapReader washer(geometry.get("washer", "a map with inner_diameter, outer_diameter, thickness"),
                         {"inner_diameter", "outer_diameter", "thickness"});
  const MapReader gear(geometry.get("gear", "a map with inner_diameter, outer_diameter, thickness, tilt"),
                       {"inner_diameter", "outer_diameter", "thickness", "tilt"});

  const Annulus washer_annulus = read_annulus(washer);
  out.washer.inner_radius = washer_annulus.inner_radius;
  out.washer.outer_radius = washer_annulus.outer_radius;
  out.washer.thickness = washer.quantity("thickness", si::length, bounds::thickness);

  // The carrier's face is modelled as covering exactly the washer annulus (MODEL.md 7).
  out.carrier.inner_radius = out.washer.inner_radius;
  out.carrier.outer_radius = out.washer.outer_radius;
  out.carrier.thickness = carrier.quantity("thickness", si::length, bounds::thickness);

  const Annulus gear_annulus = read_annulus(gear);
  out.gear.inner_radius = gear_annulus.inner_radius;
  out.gear.outer_radius = gear_annulus.outer_radius;
  out.gear.thickness = gear.quantity("thickness", si::length, bounds::thickness);
  out.gear.tilt = gear.quantity("tilt", si::angle, bounds::tilt, out.gear.tilt);

  // Film 2 lives on the overlap of the washer and gear annuli; without one the washer
  // could not carry the gear's load.
  const double overlap_inner = std::max(out.washer.inner_radius, out.gear.inner_radius);
  const double overlap_outer = std::min(out.washer.outer_radius, out.gear.outer_radius);
  if (overlap_inner >= overlap_outer) {
    const Node node = out.gear.inner_radius >= out.washer.outer_radius
                          ? gear.get("inner_diameter", "")
                          : gear.get("outer_diameter", "");
    node.fail(fmt::format(
        "{}: the gear annulus ({} m to {} m in diameter) does not overlap the washer annulus "
        "({} m to {} m): film 2 would be empty; the annuli must overlap",
        node.path(), 2 * out.gear.inner_radius, 2 * out.gear.outer_radius,
        2 * out.washer.inner_radius, 2 * out.washer.outer_radius));
  }
}

Material read_material(const MapReader& materials, std::string_view component) {
  const MapReader steel = materials.map(component, {"youngs_modulus", "poisson_ratio", "yield_strength",
                                                    "conductivity", "density", "specific_heat"});
  Material m;
  m.youngs_modulus = steel.quantity("youngs_modulus", si::stress, bounds::youngs_modulus, m.youngs_modulus);
  m.poisson_ratio = steel.quantity("poisson_ratio", si::dimensionless,
                                   {.low = 0.0, .low_open = true, .high = 0.5, .high_open = true},
                                   m.poisson_ratio);
  m.yield_strength = steel.quantity("yield_strength", si::stress, bounds::yield_strength, m.yield_strength);
  m.conductivity = steel.quantity("conductivity", si::conductivity, bounds::solid_conductivity, m.conductivity);
  m.density = steel.quantity("density", si::density, bounds::density, m.density);
  m.specific_heat = steel.quantity("specific_heat", si::specific_heat, bounds::specific_heat, m.specific_heat);
  return m;
}

Roughness read_roughness(const MapReader& surfaces, std::string_view component) {
  const MapReader face = surfaces.map(component, {"Ra", "Rq"});
  Roughness r;
  r.ra = face.quantity("Ra", si::length, bounds::roughness, r.ra);
  r.rq = face.quantity("Rq", si::length, bounds::roughness, r.rq);
  return r;
}

// Summit statistics of the carrier-washer pair (film 1, the paper's sliding film). The
// defaults follow MODEL.md section 4: sigma_s = the combined sigma, eta = eta_R_sigma/(R sigma_s).
AsperityParameters read_asperities(const MapReader& surfaces, const Scene& scene) {
  const MapReader summits = surfaces.map(
      "asperities", {"summit_radius", "summit_sigma", "summit_density", "eta_R_sigma"});
  AsperityParameters a;
  a.summit_radius = summits.quantity("summit_radius", si::length, bounds::summit_radius, a.summit_radius);
  const double combined_sigma = std::hypot(scene.carrier.roughness.rq, scene.washer.roughness.rq);
  a.summit_sigma = summits.quantity("summit_sigma", si::length, bounds::roughness, combined_sigma);
  if (summits.has("summit_density") && summits.has("eta_R_sigma")) {
    const Node node = summits.get("eta_R_sigma", "");
    node.fail(fmt::format("{}: give either summit_density or eta_R_sigma, not both "
                          "(eta_R_sigma only sets the default summit_density)",
                          node.path()));
  }
  if (summits.has("summit_density")) {
    a.summit_density = summits.quantity("summit_density", si::areal_density, bounds::summit_density);
  } else {
    const double eta_r_sigma = summits.quantity("eta_R_sigma", si::dimensionless, bounds::eta_r_sigma, a.eta_r_sigma);
    a.summit_density = eta_r_sigma / (a.summit_radius * a.summit_sigma);
  }
  // From the density either way: a described scene gives the density, and must read back
  // the same product to the last bit, not one an ulp from the eta_R_sigma first written.
  a.eta_r_sigma = a.summit_density * a.summit_radius * a.summit_sigma;
  return a;
}

}  // namespace

void read_bodies(const MapReader& scene, Scene& out) {
  read_geometry(scene, out);

  const MapReader materials = scene.map("materials", {kComponentNames.begin(), kComponentNames.end()});
  out.carrier.material = read_material(materials, "carrier");
  out.washer.material = read_material(materials, "washer");
  out.gear.material = read_material(materials, "gear");

  const MapReader surfaces = scene.map("surfaces", {"carrier", "washer", "gear", "asperities"});
  out.carrier.roughness = read_roughness(surfaces, "carrier");
  out.washer.roughness = read_roughness(surfaces, "washer");
  out.gear.roughness = read_roughness(surfaces, "gear");
  out.asperities = read_asperities(surfaces, out);
}

}  // namespace twb::scene_io
