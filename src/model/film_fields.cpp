// The fields of a solved state on each film's polar grid (film_fields.h): node values
// read from the unknowns and the gap plane, for maps. The reported integrals (forces,
// torque, heat) do not come from here: film_loads.cpp integrates over each cell.
#include <cmath>

#include "model/bearing_model.h"
#include "model/film_gap.h"
#include "model/film_roughness.h"

namespace twb {

std::vector<FilmFields> BearingModel::fields(std::span<const double> u) const {
  const double ambient = scene_.operating.ambient;
  const bool thermal = scene_.effects.thermal;
  std::vector<FilmFields> out;
  for (const Film& film : films_) {
    const FilmMesh& m = film.mesh;
    const FilmGap gaps(*this, u, film);
    const FilmRoughness roughness(*this, u, film);  // where the faces run in, the summits per node
    const std::size_t n = std::size_t(m.node_count());
    FilmFields f{film.number, film.sliding, m, {}, {}, {}, {}, {}, {}, {}};
    for (auto* v : {&f.gap, &f.pressure, &f.contact_pressure, &f.film_temperature, &f.surface_temperature,
                    &f.viscosity})
      v->assign(n, 0.0);
    for (int i = 0; i < m.radial_nodes(); ++i) {
      const double r = m.radius(i);
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        const std::size_t k = std::size_t(m.node(i, j));
        // On a relief's edge the node's gap is its control volume's mean (face_relief.h).
        const double h = gaps.mean(i, j);
        f.gap[k] = h;
        f.pressure[k] = pressure_at(u, film, i, j);
        // The contact law's value at the node's gap, for a map. The reported contact
        // force is not the sum of these times node areas: near the tight rim the law
        // changes within a fraction of a cell, so film_loads.cpp integrates it over each
        // cell with a high-order rule. Beyond the cutoff (p < 1e-20 p(0)) the model
        // counts no contact, and neither does the map.
        if (contact_ && h <= contact_cutoff_)
          f.contact_pressure[k] = roughness.varies()
                                      ? scaled_contact_->pressure(h, roughness.at_node(int(k)).sigma / film.sigma).value
                                      : contact_->pressure(h).value;
        f.film_temperature[k] =
            thermal ? temperature_of(u, film.temperature_row(int(k))) : ambient;
        f.surface_temperature[k] = 0.5 * (face_temperature(u, film.lower, r, j, nullptr) +
                                          face_temperature(u, film.upper, r, j, nullptr));
        f.viscosity[k] = viscosity(viscosity_temperature(u, film, i, j, nullptr)).value;
      }
    }
    if (plate_.elastic()) f.washer_deflection = washer_deflection_at(u, film);
    out.push_back(std::move(f));
  }
  return out;
}

// The deflection at each node of a film (towards film 2): its part of the gap (film 1's
// opens by w, film 2's closes by it), from the plate's shares.
std::vector<double> BearingModel::washer_deflection_at(std::span<const double> u, const Film& film) const {
  const FilmMesh& m = film.mesh;
  const double towards = film.upper == ComponentId::washer ? 1.0 : -1.0;
  std::vector<double> w(std::size_t(m.node_count()), 0.0);
  for (int i = 0; i < m.radial_nodes(); ++i)
    for (const WasherPlate::Share& share : plate_.of(film, i))
      for (int j = 0; j < m.circumferential_nodes(); ++j)
        w[std::size_t(m.node(i, j))] += towards * share.weight * plate_.deflection_ref *
                                        u[std::size_t(plate_.deflection + share.ring * plate_.circumferential_nodes + j)];
  return w;
}

}  // namespace twb
