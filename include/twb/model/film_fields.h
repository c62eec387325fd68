// The fields of a solved state on each film's polar grid (docs/physics.md section 9, "fields
// on request"): what a polar map of the film shows, node by node. Every film has them,
// whether it is simulated for pressure and heat or not: its gap and asperity contact
// exist as soon as the bodies are placed.
#pragma once

#include <vector>

#include "twb/model/film_mesh.h"

namespace twb {

// One film's fields; node (i, j) of the mesh (radius(i), angle(j) in the load frame,
// θ counter-clockwise from +x seen from +z) is entry mesh.node(i, j) of every vector.
struct FilmFields {
  int film = 1;  // 1: carrier–washer, 2: washer–gear
  bool sliding = false;
  FilmMesh mesh;
  // Nominal film thickness h (m): the separation of the mean surface planes; ≤ 0 where
  // the rigid planes overlap at a tight rim (docs/physics.md section 3).
  std::vector<double> gap;
  // Fluid pressure (Pa, gauge): the node's pressure unknown; 0 on the film's edges
  // (boundary condition) and on a film without pressure unknowns.
  std::vector<double> pressure;
  // Asperity contact pressure (Pa): the statistical law at the node's own gap, 0 without
  // the asperity_contact effect.
  std::vector<double> contact_pressure;
  // Temperatures (K): the film node's own Tf, and the mean of the two bounding faces
  // (the paper's viscosity temperature); both the ambient without the thermal effect,
  // which holds everything at ambient.
  std::vector<double> film_temperature;
  std::vector<double> surface_temperature;
  // Viscosity (Pa·s) at the temperature the scene's effects.viscosity_temperature names.
  std::vector<double> viscosity;
  // With the elastic washer (docs/physics.md section 21): its deflection at the node (m),
  // towards film 2, from its rigid plane; empty without.
  std::vector<double> washer_deflection;
};

}  // namespace twb
