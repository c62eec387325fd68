#include "twb/results/fields_table.h"

#include <algorithm>
#include <regex>
#include <set>

#include <fmt/format.h>

#include "result_cells.h"
#include "results/atomic_file.h"

namespace twb {

using cells::kelvin_offset;

ResultTable fields_table(const std::vector<FilmFields>& films) {
  ResultTable t;
  const auto film = t.count("film"), sliding = t.count("sliding"), r = t.number("r_m"), theta = t.number("theta_rad"),
             h = t.number("h_m"), p = t.number("p_Pa"), p_contact = t.number("p_contact_Pa"),
             t_film = t.number("T_film_C"), t_surfaces = t.number("T_surfaces_C"),
             viscosity = t.number("viscosity_Pa_s");
  // The elastic washer's deflection, only where a film has it (physics §21).
  const bool bends = std::any_of(films.begin(), films.end(), [](const FilmFields& f) { return !f.washer_deflection.empty(); });
  const auto deflection = bends ? t.number("washer_deflection_m") : ResultTable::Column{};
  for (const FilmFields& f : films) {
    const FilmMesh& m = f.mesh;
    for (int i = 0; i < m.radial_nodes(); ++i)
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        const std::size_t k = std::size_t(m.node(i, j));
        t.put_count(film, f.film);
        t.put_count(sliding, f.sliding ? 1 : 0);
        t.put_number(r, m.radius(i));
        t.put_number(theta, m.angle(j));
        t.put_number(h, f.gap[k]);
        t.put_number(p, f.pressure[k]);
        t.put_number(p_contact, f.contact_pressure[k]);
        t.put_number(t_film, f.film_temperature[k] - kelvin_offset);
        t.put_number(t_surfaces, f.surface_temperature[k] - kelvin_offset);
        t.put_number(viscosity, f.viscosity[k]);
        if (bends) t.put_number(deflection, f.washer_deflection.empty() ? 0.0 : f.washer_deflection[k]);
      }
  }
  return t;
}

std::string fields_csv(const std::vector<FilmFields>& films) { return fields_table(films).csv(); }

std::string fields_file_name(std::size_t row) { return fmt::format("state_{:04d}.csv", row); }

std::size_t write_state_fields(const std::filesystem::path& dir, const std::vector<SolvedState>& rows,
                               int significant_digits) {
  namespace fs = std::filesystem;
  const fs::path fields_dir = dir / "fields";
  std::set<std::string> written;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k].fields.empty()) continue;
    const std::string name = fields_file_name(k + 1);
    write_file_atomically(fields_dir / name, fields_table(rows[k].fields).csv(significant_digits));
    written.insert(name);
  }
  if (!fs::is_directory(fields_dir)) return written.size();
  // Only names twb writes are touched; anything else in the directory stays.
  static const std::regex ours(R"(state_[0-9]{4,}\.csv)");
  for (const fs::directory_entry& e : fs::directory_iterator(fields_dir)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && std::regex_match(name, ours) && !written.contains(name)) fs::remove(e.path());
  }
  if (fs::is_empty(fields_dir)) fs::remove(fields_dir);
  return written.size();
}

}  // namespace twb
