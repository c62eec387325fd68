// describe_scene: the resolved scene written back as a scene file, so a run's inputs can be
// stored beside its results and replayed exactly.
#include <fmt/format.h>

#include "scene_names.h"
#include "scene_text.h"
#include "studies/study_section.h"
#include "twb/scene/worn_washer.h"
#include "twb/scene/scene_loader.h"

namespace twb {
namespace {

using namespace scene_io;

void write_effects(SceneText& w, const Effects& e) {
  w.line(0, "effects:");
  if (e.hydrodynamics && e.cavitation == CavitationModel::jfo)
    w.line(1, fmt::format("- hydrodynamics: {{cavitation: jfo, cavity_pressure: {}}}", quantity(e.cavity_pressure, "Pa")));
  else if (e.hydrodynamics)
    w.line(1, fmt::format("- hydrodynamics: {{cavitation: {}}}", kCavitationModels.name(e.cavitation)));
  if (e.flow_factors) w.line(1, "- flow_factors");
  if (e.asperity_contact) w.line(1, "- asperity_contact");
  if (e.thermal)
    w.line(1, fmt::format("- thermal: {{viscosity_temperature: {}, carrier_temperature: {}}}",
                          kViscosityTemperatures.name(e.viscosity_temperature),
                          kCarrierTemperatures.name(e.carrier_temperature)));
  if (e.thermal_deformation)
    w.line(1, fmt::format("- thermal_deformation: {{face_expansion: {}}}", kFaceExpansions.name(e.face_expansion)));
  if (e.convection) w.line(1, "- convection");
  if (e.wear) w.line(1, "- wear");
  if (e.elastic_washer) w.line(1, "- elastic_washer");
}

// The width as the scene gave it, which the grid rounds again to the same whole cells (a
// groove parameter places the grooves anew from it), with what the grid holds beside it;
// the land's inlet as the share of its whole cells (docs/physics.md section 14).
void write_grooves(SceneText& w, const Grooves& g, const Scene& s) {
  w.line(2, "grooves:");
  w.entry(3, "count", fmt::format("{}", g.count));
  w.entry(3, "face", g.film == 1 ? "film_1" : "film_2");
  const double mean_radius = 0.5 * (s.washer.inner_radius + s.washer.outer_radius);
  w.entry(3, "width", quantity(g.written_width, "rad"),
          fmt::format("on the grid: {} cells of the {} round it, {:.6g} rad, {:.4g} mm at the mean radius", g.cells,
                      s.mesh.circumferential_nodes, g.width, 1e3 * g.width * mean_radius));
  w.entry(3, "depth", quantity(g.depth, "m"));
  if (const std::optional<GrooveDam>& dam = g.closed_at) {
    w.entry(3, "closed_at", quantity(dam->written_radius, "m"),
            fmt::format("on the grid: radial line {} of the grooved film's {}, {:.4g} mm", dam->line,
                        s.mesh.radial_nodes, 1e3 * dam->radius));
    w.entry(3, "open_at", std::string(kGrooveOpenings.name(dam->open_at)));
  }
  if (g.land.shape == LandShape::flat) return;
  w.line(3, "land:");
  w.line(4, fmt::format("{}:", g.land.shape == LandShape::taper ? "taper" : "step"));
  w.entry(5, "depth", quantity(g.land.depth, "m"));
  w.entry(5, "fraction", quantity(g.land.fraction, "1"), "of the land, whole cells");
}

void write_geometry(SceneText& w, const Scene& s) {
  w.line(0, "geometry:");
  w.line(1, "carrier:  # its face covers the washer annulus");
  w.entry(2, "thickness", quantity(s.carrier.thickness, "m"));
  w.line(1, "washer:");
  w.entry(2, "inner_diameter", quantity(2 * s.washer.inner_radius, "m"));
  w.entry(2, "outer_diameter", quantity(2 * s.washer.outer_radius, "m"));
  w.entry(2, "thickness", quantity(s.washer.thickness, "m"));
  if (const std::optional<Grooves>& g = s.washer.grooves) write_grooves(w, *g, s);
  w.line(1, "gear:");
  w.entry(2, "inner_diameter", quantity(2 * s.gear.inner_radius, "m"));
  w.entry(2, "outer_diameter", quantity(2 * s.gear.outer_radius, "m"));
  w.entry(2, "thickness", quantity(s.gear.thickness, "m"));
  w.entry(2, "tilt", quantity(s.gear.tilt, "rad"));
  if (s.gear.axial_play) w.entry(2, "axial_play", quantity(*s.gear.axial_play, "m"));
}

void write_materials(SceneText& w, const Scene& s) {
  w.line(0, "materials:");
  for (const auto& [name, component] :
       {std::pair{"carrier", &s.carrier}, std::pair{"washer", &s.washer}, std::pair{"gear", &s.gear}}) {
    const Material& m = component->material;
    // The library's name only as a note: the values are written out, and a later library
    // (other values, a limit added, a name gone) must not change the scene read back.
    w.line(1, m.library.empty() ? fmt::format("{}:", name)
                                : fmt::format("{}:  # the library's {} (docs/materials.md)", name, m.library));
    if (m.modulus_by_temperature.empty()) {
      w.entry(2, "youngs_modulus", quantity(m.youngs_modulus, "Pa"));
    } else {
      w.line(2, fmt::format("modulus_by_temperature:  # {} Pa at 23 degC", m.youngs_modulus));
      for (const ModulusAt& point : m.modulus_by_temperature)
        w.line(3, fmt::format("- {{temperature: {}, modulus: {}}}  # {:.2f} degC", quantity(point.temperature, "K"),
                              quantity(point.modulus, "Pa"), point.temperature - 273.15));
    }
    w.entry(2, "poisson_ratio", quantity(m.poisson_ratio, "1"));
    w.entry(2, "yield_strength", quantity(m.yield_strength, "Pa"));
    w.entry(2, "conductivity", quantity(m.conductivity, "W/(m K)"));
    w.entry(2, "density", quantity(m.density, "kg/m^3"));
    w.entry(2, "specific_heat", quantity(m.specific_heat, "J/(kg K)"));
    w.entry(2, "thermal_expansion", quantity(m.thermal_expansion, "1/K"));
    if (m.max_temperature)
      w.entry(2, "max_temperature", quantity(*m.max_temperature, "K"),
              fmt::format("{:.2f} degC", *m.max_temperature - 273.15));
    if (m.pv_limit)
      w.entry(2, "pv_limit", quantity(*m.pv_limit, "Pa m/s"), fmt::format("{:.3g} MPa m/s", 1e-6 * *m.pv_limit));
  }
}

void write_surfaces(SceneText& w, const Scene& s) {
  w.line(0, "surfaces:");
  for (const auto& [name, component] :
       {std::pair{"carrier", &s.carrier}, std::pair{"washer", &s.washer}, std::pair{"gear", &s.gear}}) {
    w.line(1, fmt::format("{}:", name));
    w.entry(2, "Ra", quantity(component->roughness.ra, "m"));
    w.entry(2, "Rq", quantity(component->roughness.rq, "m"));
    if (component->roughness.wear_rate) w.entry(2, "wear_rate", quantity(*component->roughness.wear_rate, "m^3/(N m)"));
    if (component->roughness.run_in_rq) w.entry(2, "run_in_rq", quantity(*component->roughness.run_in_rq, "m"));
  }
  const AsperityParameters& a = s.asperities;
  w.line(1, "asperities:");
  w.entry(2, "summit_radius", quantity(a.summit_radius, "m"));
  w.entry(2, "summit_sigma", quantity(a.summit_sigma, "m"));
  // The density is written rather than eta_R_sigma: the file may hold only one of them.
  w.entry(2, "summit_density", quantity(a.summit_density, "1/m^2"),
          fmt::format("eta_R_sigma = {}", a.eta_r_sigma));
}

void write_operation(SceneText& w, const Scene& s) {
  const Lubricant& l = s.lubricant;
  w.line(0, "lubricant:");
  w.entry(1, "conductivity", quantity(l.conductivity, "W/(m K)"));
  w.entry(1, "max_temperature", quantity(l.max_temperature, "K"));
  w.entry(1, "flash_temperature", quantity(l.flash_temperature, "K"));
  w.entry(1, "density", quantity(l.density, "kg/m^3"), "at 15 degC");
  w.entry(1, "density_expansion", quantity(l.density_expansion, "1/K"));
  w.entry(1, "specific_heat", quantity(l.specific_heat, "J/(kg K)"));
  if (l.supply)
    w.line(1, fmt::format("supply: {{pressure: {} Pa, at: {}{}, carry_over: {}}}", l.supply->pressure,
                          kSupplyInlets.name(l.supply->at),
                          l.supply->temperature ? fmt::format(", temperature: {}", quantity(*l.supply->temperature, "K"))
                                                : std::string(),
                          l.supply->carry_over));
  w.line(1, "viscosity:");
  w.entry(2, "model", std::string(kViscosityModels.name(l.viscosity_model)));
  if (l.viscosity_model == ViscosityModel::roelands) {
    w.entry(2, "mu_infinity", quantity(l.mu_infinity, "Pa s"));
    w.entry(2, "G0", quantity(l.g0, "1"));
    w.entry(2, "S0", quantity(l.s0, "1"));
  } else {
    w.entry(2, "value", quantity(l.constant_viscosity, "Pa s"));
  }

  w.line(0, "limits:");
  if (s.limits.min_film_ratio) w.entry(1, "min_film_ratio", quantity(*s.limits.min_film_ratio, "1"));
  w.entry(1, "scuffing_temperature", quantity(s.limits.scuffing_temperature, "K"));
  if (s.limits.wear_depth) w.entry(1, "wear_depth", quantity(*s.limits.wear_depth, "m"));

  const Operating& o = s.operating;
  w.line(0, "operating:");
  w.entry(1, "load", quantity(o.load, "N"));
  w.entry(1, "speed", quantity(o.speed, "rad/s"));
  w.entry(1, "sliding", std::string(kSlidingFilms.name(o.sliding)));
  w.entry(1, "ambient", quantity(o.ambient, "K"), fmt::format("{:.2f} degC", o.ambient - 273.15));

  w.line(0, "friction:");
  w.entry(1, "law", std::string(kFrictionLaws.name(s.friction.law)));
  if (s.friction.law == FrictionLaw::constant)
    w.entry(1, "coefficient", quantity(s.friction.coefficient, "1"));
}

void write_numerics(SceneText& w, const Scene& s) {
  w.line(0, "mesh:");
  w.entry(1, "radial_nodes", fmt::format("{}", s.mesh.radial_nodes));
  w.entry(1, "circumferential_nodes", fmt::format("{}", s.mesh.circumferential_nodes),
          s.washer.grooves ? fmt::format("a multiple of the {} grooves", s.washer.grooves->count) : std::string());
  w.entry(1, "contact_quadrature", fmt::format("{}", s.mesh.contact_quadrature));
  w.entry(1, "flat_contact_quadrature", fmt::format("{}", s.mesh.flat_contact_quadrature));
  w.entry(1, "max_refinements", fmt::format("{}", s.mesh.max_refinements));

  w.line(0, "solver:");
  w.entry(1, "method", std::string(kSolverMethods.name(s.solver.method)));
  if (s.solver.method == SolverMethod::paper) w.entry(1, "over_relaxation", quantity(s.solver.over_relaxation, "1"));
  w.entry(1, "residual_tolerance", quantity(s.solver.residual_tolerance, "1"));
  w.entry(1, "step_tolerance", quantity(s.solver.step_tolerance, "1"));
  w.entry(1, "max_iterations", fmt::format("{}", s.solver.max_iterations));
  w.entry(1, "cold_start_film", quantity(s.solver.cold_start_film, "1"));

  w.line(0, "study:");
  w.entry(1, "type", std::string(kStudyTypes.name(s.study.type())));
  study_section(s.study.type()).write(w, s.study);

  w.line(0, "output:");
  w.entry(1, "directory", quoted(s.output.directory));
  w.entry(1, "fields", s.output.fields ? "true" : "false");
}

}  // namespace

std::string_view scene_name(SlidingFilm film) { return kSlidingFilms.name(film); }
std::string_view scene_name(StudyType type) { return kStudyTypes.name(type); }

std::string describe_scene(const Scene& scene) {
  SceneText w;
  w.line(0, "# The resolved scene: every default filled in, every value in SI.");
  if (!scene.source.empty()) w.line(0, fmt::format("# Read from {}", scene.source));
  if (scene.worn)
    w.line(0, fmt::format("# The washer as a life wore it: {:.6g} h ({}), its depths held", scene.worn->time / 3600.0,
                          scene.worn->source));
  write_effects(w, scene.effects);
  write_geometry(w, scene);
  write_materials(w, scene);
  write_surfaces(w, scene);
  write_operation(w, scene);
  write_numerics(w, scene);
  return std::move(w).text();
}

}  // namespace twb
