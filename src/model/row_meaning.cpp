// What a residual row of the bearing means, in the physics' words and at its place on
// the film, for the solver's diagnoses: "which balance, which film, which node"
// instead of a row number.
#include <numbers>

#include <fmt/format.h>

#include "model/bearing_model.h"

namespace twb {

namespace {

std::string place(const FilmMesh& mesh, int i, int j) {
  return fmt::format("node ({}, {}) at r = {:.3g} mm, theta = {:.3g} deg", i, j, mesh.radius(i) * 1e3,
                     mesh.angle(j) * 180.0 / std::numbers::pi);
}

const char* component_name(ComponentId id) {
  switch (id) {
    case ComponentId::carrier: return "carrier";
    case ComponentId::washer: return "washer";
    case ComponentId::gear: return "gear";
  }
  return "?";
}

}  // namespace

std::string BearingModel::describe_row(Index k) const {
  if (k >= rigid_offset_ && k < rigid_offset_ + 4) {
    static constexpr const char* rigid[] = {
        "the washer's axial force balance (film 1 against film 2)", "the washer's moment balance about x",
        "the washer's moment balance about y", "the gear's axial force balance (film 2 against the load)"};
    if (k == rigid_offset_ + 3 && gear_stop())
      return "the gear's axial balance with its stop (film 2 against the load, or the gear on its stop at its axial "
             "play)";
    return rigid[k - rigid_offset_];
  }
  for (const Film& f : films_) {
    const int nt = f.mesh.circumferential_nodes();
    if (f.pressure_offset >= 0 && k >= f.pressure_offset && k < f.pressure_offset + f.mesh.interior_count()) {
      const Index n = k - f.pressure_offset;
      return fmt::format("the {} of film {} at {}",
                         f.content_offset >= 0 ? "cavitation condition (p >= 0, content <= 1)"
                                               : "flow balance (Reynolds, with cavitation)",
                         f.number, place(f.mesh, int(n / nt) + 1, int(n % nt)));
    }
    if (f.content_offset >= 0 && k >= f.content_offset && k < f.content_offset + f.mesh.interior_count()) {
      const Index n = k - f.content_offset;
      return fmt::format("the mass-conserving flow balance of film {} at {}", f.number,
                         place(f.mesh, int(n / nt) + 1, int(n % nt)));
    }
    if (f.temperature_offset >= 0 && k >= f.temperature_offset && k < f.temperature_offset + f.mesh.node_count()) {
      const Index n = k - f.temperature_offset;
      return fmt::format("the heat balance of film {}'s film node at {}", f.number,
                         place(f.mesh, int(n / nt), int(n % nt)));
    }
  }
  if (plate_.elastic()) {
    // The plate's rows on film 1's grid (physics §21): [E1]'s two per node, the edges'
    // fluxes from [E2] and [E3], then the three conditions that hold the rigid plane (the
    // block the layout places after the moments).
    const FilmMesh& grid = films_.front().mesh;
    const Index n = grid.node_count(), nt = grid.circumferential_nodes();
    if (k >= plate_.deflection && k < plate_.deflection + n)
      return fmt::format("the washer plate's curvature ([E1], at an edge with the moment-free [E2]) at {}",
                         place(grid, int((k - plate_.deflection) / nt), int((k - plate_.deflection) % nt)));
    if (k >= plate_.moment && k < plate_.moment + n)
      return fmt::format("the washer plate's load balance ([E1], at an edge with the shear-free [E3]) at {}",
                         place(grid, int((k - plate_.moment) / nt), int((k - plate_.moment) % nt)));
    static constexpr const char* rigid_plane[] = {"the integral of w dA zero", "the integral of w x dA zero",
                                                  "the integral of w y dA zero"};
    if (k >= plate_.moment + n && k < plate_.moment + n + 3)
      return fmt::format("the washer plate's rigid plane ({})", rigid_plane[k - plate_.moment - n]);
  }
  for (const ComponentHeat& c : components_) {
    if (k < c.offset || k >= c.offset + c.node_count()) continue;
    const Index n = k - c.offset;
    if (c.axisymmetric)
      return fmt::format("the heat balance of the {} (axisymmetric) at r = {:.3g} mm", component_name(c.id),
                         c.grid.radius(int(n)) * 1e3);
    const int nt = c.grid.circumferential_nodes();
    return fmt::format("the heat balance of the {} at {}", component_name(c.id),
                       place(c.grid, int(n / nt), int(n % nt)));
  }
  return block_name(k);
}

}  // namespace twb
