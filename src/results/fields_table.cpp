#include "twb/results/fields_table.h"

#include <regex>
#include <set>

#include "result_cells.h"
#include "results/atomic_file.h"

namespace twb {

using cells::finite;
using cells::kelvin_offset;

std::string fields_csv(const std::vector<FilmFields>& films) {
  std::string out = "film,sliding,r_m,theta_rad,h_m,p_Pa,p_contact_Pa,T_film_C,T_surfaces_C,viscosity_Pa_s\n";
  for (const FilmFields& f : films) {
    const FilmMesh& m = f.mesh;
    for (int i = 0; i < m.radial_nodes(); ++i)
      for (int j = 0; j < m.circumferential_nodes(); ++j) {
        const std::size_t k = std::size_t(m.node(i, j));
        out += fmt::format("{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", f.film,
                           f.sliding ? 1 : 0, finite(m.radius(i), "r"), finite(m.angle(j), "theta"),
                           finite(f.gap[k], "h"), finite(f.pressure[k], "p"),
                           finite(f.contact_pressure[k], "p_contact"),
                           finite(f.film_temperature[k] - kelvin_offset, "T_film"),
                           finite(f.surface_temperature[k] - kelvin_offset, "T_surfaces"),
                           finite(f.viscosity[k], "viscosity"));
      }
  }
  return out;
}

std::string fields_file_name(std::size_t row) { return fmt::format("state_{:04d}.csv", row); }

std::size_t write_state_fields(const std::filesystem::path& dir, const std::vector<SolvedState>& rows) {
  namespace fs = std::filesystem;
  const fs::path fields_dir = dir / "fields";
  std::set<std::string> written;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k].fields.empty()) continue;
    const std::string name = fields_file_name(k + 1);
    write_file_atomically(fields_dir / name, fields_csv(rows[k].fields));
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
