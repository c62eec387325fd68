// The library as docs/materials.md shows it (`twb materials`): one table of the values a
// scene takes, the moduli over temperature, the coatings' thicknesses, and the sources.
#include <string>

#include <fmt/format.h>

#include "twb/scene/material_library.h"

namespace twb {
namespace {

constexpr double kCelsius = 273.15;

std::string optional_value(const std::optional<double>& value, double scale, double offset = 0.0) {
  return value ? fmt::format("{:.4g}", (*value - offset) * scale) : std::string("–");
}

std::string value_row(const LibraryMaterial& m) {
  const Material& p = m.properties;
  return fmt::format("| `{}` | {} | {:.4g} | {:.3g} | {:.4g} | {:.3g} | {:.4g} | {:.4g} | {:.3g} | {} | {} | {} |\n",
                     m.name, m.description, 1e-9 * p.youngs_modulus, p.poisson_ratio, 1e-6 * p.yield_strength,
                     p.conductivity, p.density, p.specific_heat, 1e6 * p.thermal_expansion,
                     optional_value(p.max_temperature, 1.0, kCelsius), optional_value(p.pv_limit, 1e-6),
                     optional_value(m.glass_transition, 1.0, kCelsius));
}

std::string modulus_line(const LibraryMaterial& m) {
  std::string points;
  for (const ModulusAt& at : m.properties.modulus_by_temperature)
    points += fmt::format("{}{:.4g} degC: {:.3g} GPa", points.empty() ? "" : ", ", at.temperature - kCelsius,
                          1e-9 * at.modulus);
  return fmt::format("- `{}`: {}\n", m.name, points);
}

}  // namespace

std::string material_library_markdown() {
  std::string out =
      "| name | material | E GPa | ν | yield MPa | K W/(m K) | ρ kg/m³ | c J/(kg K) | α 1e-6/K | limit °C | "
      "PV MPa m/s | T_g °C |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const LibraryMaterial& m : material_library()) out += value_row(m);
  out += "\nThe modulus over temperature, where the data sheet gives it:\n\n";
  for (const LibraryMaterial& m : material_library())
    if (!m.properties.modulus_by_temperature.empty()) out += modulus_line(m);
  out += "\nThe coatings' usual thicknesses:\n\n";
  for (const LibraryMaterial& m : material_library())
    if (m.coating_thickness)
      out += fmt::format("- `{}`: {:.3g} to {:.3g} µm\n", m.name, 1e6 * m.coating_thickness->first,
                         1e6 * m.coating_thickness->second);
  out += "\nSources:\n\n";
  for (const LibraryMaterial& m : material_library()) out += fmt::format("- `{}`: {}\n", m.name, m.sources);
  return out;
}

}  // namespace twb
