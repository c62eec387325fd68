// The paper's Table 1 case built in code, for tests that must not depend on the scene
// loader; the loader's own tests check that configs/jackson_green_2006.yaml resolves
// to the same values.
#pragma once

#include <cmath>
#include <numbers>

#include "twb/scene/scene.h"

namespace twb::testing {

inline Scene table1_scene(bool hydrodynamics, bool flow_factors, bool contact, bool thermal,
                          double speed = 545.0, double load = 500.0) {
  Scene s;
  s.source = "table1 (in code)";
  s.effects.hydrodynamics = hydrodynamics;
  s.effects.flow_factors = flow_factors;
  s.effects.asperity_contact = contact;
  s.effects.thermal = thermal;
  // Each body's dimensions alone; its material, roughness and play are set below or kept
  // at their defaults.
  const auto body = [](double inner_radius, double outer_radius, double thickness, double tilt) {
    Component c;
    c.inner_radius = inner_radius;
    c.outer_radius = outer_radius;
    c.thickness = thickness;
    c.tilt = tilt;
    return c;
  };
  s.washer = body(11.1e-3 / 2, 22.7e-3 / 2, 0.635e-3, 0.0);
  s.gear = body(15.6e-3 / 2, 22.7e-3 / 2, 10e-3, 2e-3);
  s.carrier = body(11.1e-3 / 2, 22.7e-3 / 2, 10e-3, 0.0);
  const double sigma = std::hypot(0.515e-6, 0.515e-6);
  s.asperities.summit_radius = 20e-6;
  s.asperities.summit_sigma = sigma;
  s.asperities.eta_r_sigma = 0.05;
  s.asperities.summit_density = 0.05 / (20e-6 * sigma);
  s.operating.load = load;
  s.operating.speed = speed;
  return s;
}

// A wide parallel annulus for the closed forms of a film alone (docs/physics.md section
// 14): washer, gear and carrier faces from r = 10 to 30 mm, no tilt, film 2 sliding over
// the washer held by the carrier, an isothermal oil of constant viscosity.
inline Scene wide_parallel_annulus(double speed, double load) {
  Scene s = table1_scene(true, false, true, false, speed, load);
  s.washer.inner_radius = s.gear.inner_radius = s.carrier.inner_radius = 10e-3;
  s.washer.outer_radius = s.gear.outer_radius = s.carrier.outer_radius = 30e-3;
  s.gear.tilt = 0.0;
  s.operating.sliding = SlidingFilm::washer_gear;
  s.lubricant.viscosity_model = ViscosityModel::constant;
  return s;
}

// The coarse mesh of the model and study tests: 5 radial × 24 circumferential nodes,
// seconds per distress search. Distress moves with the mesh (about 161 N instead of
// 188 N at 545 rad/s), so tests compare twb with itself on it, not with the paper.
inline void use_coarse_mesh(Scene& s) {
  s.mesh.radial_nodes = 5;
  s.mesh.circumferential_nodes = 24;
}

// Four grooves 2 cells wide and 30 µm deep on a 32-node grid, in the face of film 2,
// which slides (the coarse grooved washer of the model and study tests), with JFO
// cavitation, as the oil supply into the grooves needs.
inline void use_four_grooves(Scene& s) {
  s.operating.sliding = SlidingFilm::washer_gear;
  s.mesh.circumferential_nodes = 32;
  Grooves g;
  g.count = 4;
  g.cells = 2;
  g.width = g.written_width = 2 * 2 * std::numbers::pi / 32;
  g.depth = 30e-6;
  s.washer.grooves = g;
  s.effects.cavitation = CavitationModel::jfo;
}

}  // namespace twb::testing
