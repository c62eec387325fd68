// The three solid bodies: their annuli and thicknesses (geometry), their materials (by
// name from the library, or field by field) and their faces' roughness (surfaces).
// docs/physics.md sections 1, 4 and 10; docs/materials.md.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "physical_bounds.h"
#include "roughness_profile.h"
#include "scene_names.h"
#include "scene_sections.h"
#include "scene/material_modulus.h"
#include "physics/summit_statistics.h"
#include "key_suggestion.h"
#include "twb/scene/material_library.h"

namespace twb::scene_io {
namespace {

// Where data sheets quote a polymer's modulus: 23 degC (ISO 291's standard atmosphere).
constexpr double kRoomTemperature = 296.15;

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
                         {"inner_diameter", "outer_diameter", "thickness", "grooves"});
  const MapReader gear(geometry.get("gear", "a map with inner_diameter, outer_diameter, thickness, tilt"),
                       {"inner_diameter", "outer_diameter", "thickness", "tilt", "axial_play"});

  const Annulus washer_annulus = read_annulus(washer);
  out.washer.inner_radius = washer_annulus.inner_radius;
  out.washer.outer_radius = washer_annulus.outer_radius;
  out.washer.thickness = washer.quantity("thickness", si::length, bounds::thickness);

  // The carrier's face is modelled as covering exactly the washer annulus (docs/physics.md 7).
  out.carrier.inner_radius = out.washer.inner_radius;
  out.carrier.outer_radius = out.washer.outer_radius;
  out.carrier.thickness = carrier.quantity("thickness", si::length, bounds::thickness);

  const Annulus gear_annulus = read_annulus(gear);
  out.gear.inner_radius = gear_annulus.inner_radius;
  out.gear.outer_radius = gear_annulus.outer_radius;
  out.gear.thickness = gear.quantity("thickness", si::length, bounds::thickness);
  out.gear.tilt = gear.quantity("tilt", si::angle, bounds::tilt, out.gear.tilt);
  if (gear.has("axial_play")) out.gear.axial_play = gear.quantity("axial_play", si::length, bounds::axial_play);

  // Film 2 lives on the overlap of the washer and gear annuli; without one the washer
  // could not carry the gear's load.
  const auto [overlap_inner, overlap_outer] = film_radii(out, 2);
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

// The library material a scene names at `node` for `component` (docs/materials.md): a
// bulk one, a coating being a face's layer and never a body.
Material library_material(const Node& node, std::string_view component) {
  const std::vector<std::string_view> bulk = library_material_names(MaterialForm::bulk);
  const std::string name = node.scalar("the name of a library material (docs/materials.md)");
  if (const LibraryMaterial* found = find_library_material(name); found && found->form == MaterialForm::coating)
    node.fail(fmt::format("{}: '{}' is a coating, a face's layer and not a body; a body's material is one of: {}",
                          node.path(), name, join(bulk)));
  Material m = find_library_material(bulk[node.choice(bulk)])->properties;
  m.library = name;
  // A library polymer or bronze may be a carrier or a gear, but its PV limit is a
  // criterion of the washer's face alone (docs/physics.md section 8).
  if (component != "washer") m.pv_limit.reset();
  return m;
}

// A library material's values are inputs of the scene as the fields it writes are (a
// sensitivity study's default differentiates them): noted under their paths, but those
// the scene gives itself, noted as they were read (the first noting of a path counts).
void note_library_values(const Node& at, std::string_view component, const Material& m, const MapReader* given) {
  const Provenance* provenance = at.provenance();
  if (!provenance || m.library.empty()) return;
  const auto note = [&](std::string_view key, std::optional<double> value, const SiUnit& unit) {
    if (!value || (given && given->has(key))) return;
    provenance->note_quantity(fmt::format("materials.{}.{}", component, key), *value, unit.symbol);
  };
  // A curve is a list, no input (scene_inputs.h); its room-temperature value is no input
  // either: setting it would replace the curve by a constant.
  if (m.modulus_by_temperature.empty()) note("youngs_modulus", m.youngs_modulus, si::stress);
  note("poisson_ratio", m.poisson_ratio, si::dimensionless);
  note("yield_strength", m.yield_strength, si::stress);
  note("conductivity", m.conductivity, si::conductivity);
  note("density", m.density, si::density);
  note("specific_heat", m.specific_heat, si::specific_heat);
  note("thermal_expansion", m.thermal_expansion, si::expansion);
  note("max_temperature", m.max_temperature, si::temperature);
  note("pv_limit", m.pv_limit, si::pv);
}

// A modulus over temperature (docs/physics.md section 23): points ascending in
// temperature, at least two (one is a constant modulus).
std::vector<ModulusAt> read_modulus_curve(const Node& list) {
  const std::vector<Node> rows = list.list("a list of points, each {temperature: 23 degC, modulus: 3.7 GPa}");
  if (rows.size() < 2)
    list.fail(fmt::format("{}: {} point{}; a modulus over temperature needs at least two (a constant modulus is "
                          "youngs_modulus)",
                          list.path(), rows.size(), rows.size() == 1 ? "" : "s"));
  std::vector<ModulusAt> curve;
  for (const Node& row : rows) {
    const MapReader point(row, {"temperature", "modulus"});
    const double t = point.quantity("temperature", si::temperature, bounds::material_temperature);
    const double e = point.quantity("modulus", si::stress, bounds::youngs_modulus);
    if (!curve.empty() && !(t > curve.back().temperature))
      row.fail(fmt::format("{}: the points must rise in temperature ({:.2f} degC after {:.2f} degC)", row.path(),
                           t - 273.15, curve.back().temperature - 273.15));
    curve.push_back({t, e});
  }
  return curve;
}

// The room-temperature modulus (23 degC) of a curve, held at its nearer end outside it;
// a point the data sheet gives there as given (the curve returns it through exp(ln E),
// within rounding only).
double room_temperature_modulus(const Material& m) {
  for (const ModulusAt& point : m.modulus_by_temperature)
    if (std::abs(point.temperature - kRoomTemperature) < 1e-9) return point.modulus;
  return modulus_curve(m)->at(kRoomTemperature).modulus;
}

// A body's material: a library material by name (`washer: peek`), a map of fields over
// one (`washer: {material: peek, yield_strength: 80 MPa}`) or over the paper's steel.
Material read_material(const MapReader& materials, std::string_view component) {
  const std::optional<Node> named = materials.find(component);
  if (named && named->yaml().IsScalar()) {
    const Material m = library_material(*named, component);
    note_library_values(*named, component, m, nullptr);
    return m;
  }
  if (named && named->yaml().IsSequence())
    named->fail(fmt::format("{}: {} is neither a library material's name (docs/materials.md: {}) nor a map of its "
                            "values",
                            named->path(), named->describe_content(),
                            join(library_material_names(MaterialForm::bulk))));
  const MapReader fields = materials.map(component, {"material", "youngs_modulus", "poisson_ratio", "yield_strength",
                                                    "conductivity", "density", "specific_heat", "thermal_expansion",
                                                    "max_temperature", "pv_limit", "modulus_by_temperature"});
  Material m = fields.has("material") ? library_material(fields.get("material", ""), component) : Material{};
  // A constant modulus replaces the named material's curve, and a curve its constant.
  if (fields.has("modulus_by_temperature")) {
    if (fields.has("youngs_modulus")) {
      const Node node = fields.get("youngs_modulus", "");
      node.fail(fmt::format("{}: give either youngs_modulus (a constant modulus) or modulus_by_temperature (its "
                            "data over temperature), not both",
                            node.path()));
    }
    m.modulus_by_temperature = read_modulus_curve(fields.get("modulus_by_temperature", ""));
    m.youngs_modulus = room_temperature_modulus(m);
  } else if (fields.has("youngs_modulus")) {
    m.modulus_by_temperature.clear();
    m.youngs_modulus = fields.quantity("youngs_modulus", si::stress, bounds::youngs_modulus);
  }
  m.poisson_ratio = fields.quantity("poisson_ratio", si::dimensionless,
                                   {.low = 0.0, .low_open = true, .high = 0.5, .high_open = true},
                                   m.poisson_ratio);
  m.yield_strength = fields.quantity("yield_strength", si::stress, bounds::yield_strength, m.yield_strength);
  m.conductivity = fields.quantity("conductivity", si::conductivity, bounds::solid_conductivity, m.conductivity);
  m.density = fields.quantity("density", si::density, bounds::density, m.density);
  m.specific_heat = fields.quantity("specific_heat", si::specific_heat, bounds::specific_heat, m.specific_heat);
  m.thermal_expansion =
      fields.quantity("thermal_expansion", si::expansion, bounds::thermal_expansion, m.thermal_expansion);
  if (fields.has("max_temperature"))
    m.max_temperature = fields.quantity("max_temperature", si::temperature, bounds::material_temperature);
  if (fields.has("pv_limit")) {
    // Only the washer's face rubs against both its neighbours: the carrier and gear are
    // steel, whose data sheets give no PV limit.
    if (component != "washer") {
      const Node node = fields.get("pv_limit", "");
      node.fail(fmt::format("{}: a PV limit is the washer's (materials.washer.pv_limit): the washer is the bearing's "
                            "bronze or polymer face",
                            node.path()));
    }
    m.pv_limit = fields.quantity("pv_limit", si::pv, bounds::pv_limit);
  }
  if (named) note_library_values(*named, component, m, &fields);
  return m;
}

// Archard's k of a face (docs/physics.md section 20): 0 (the face does not wear) or a
// rate of a real pair; below 1e-21 or above 1e-9 m³/(N·m) it is a unit slip.
double read_wear_rate(const MapReader& face, const Effects& effects) {
  const Node node = face.get("wear_rate", "");
  if (!effects.wear)
    node.fail(fmt::format("{}: a wear rate needs the effect 'wear' (without it no face wears); add wear to "
                          "'effects' or leave the rate out",
                          node.path()));
  const double k = face.quantity("wear_rate", si::wear_rate, bounds::wear_rate);
  if (k > 0.0 && k < bounds::kLeastWearRate)
    node.fail(fmt::format("{}: {:.3g} m^3/(N m) is below any material's specific wear rate ({:g}): a unit slip? "
                          "Allowed: {}",
                          node.path(), k, bounds::kLeastWearRate, bounds::wear_rate.reason));
  return k;
}

Roughness read_roughness(const MapReader& surfaces, std::string_view component, const Effects& effects) {
  const MapReader face = surfaces.map(component, {"Ra", "Rq", "wear_rate", "run_in_rq"});
  Roughness r;
  if (face.has("wear_rate")) r.wear_rate = read_wear_rate(face, effects);
  // Ra enters no equation (σ is Rq); a face given by one of the two keeps the default
  // texture's Ra/Rq for the other, so that Ra ≤ Rq holds as it does for any surface
  // (Ra is the mean |z|, Rq its root mean square).
  const double ratio = r.ra / r.rq;
  const bool has_ra = face.has("Ra"), has_rq = face.has("Rq");
  if (has_rq) r.rq = face.quantity("Rq", si::length, bounds::roughness);
  if (has_ra) r.ra = face.quantity("Ra", si::length, bounds::roughness);
  if (has_rq && !has_ra) r.ra = ratio * r.rq;
  if (has_ra && !has_rq) r.rq = r.ra / ratio;
  if (r.ra > r.rq) {
    const Node node = face.get("Ra", "");
    node.fail(fmt::format("{}: Ra {:.4g} m is larger than Rq {:.4g} m; no surface has one: Ra (the mean |z|) is at "
                          "most Rq (the root mean square of z)",
                          node.path(), r.ra, r.rq));
  }
  if (face.has("run_in_rq")) {
    const Node node = face.get("run_in_rq", "");
    if (!effects.wear)
      node.fail(fmt::format("{}: a face runs in as it wears (docs/physics.md section 20): add the effect 'wear', or "
                            "leave run_in_rq out",
                            node.path()));
    r.run_in_rq = face.quantity("run_in_rq", si::length, bounds::roughness);
    if (*r.run_in_rq > r.rq)
      node.fail(fmt::format("{}: {:.4g} m is above the face's Rq {:.4g} m: running-in smooths a face (the Rq it "
                            "runs in to is at most its Rq new)",
                            node.path(), *r.run_in_rq, r.rq));
  }
  return r;
}

}  // namespace

std::string named_file_path(const Node& node, std::string_view expected) {
  const std::filesystem::path named(node.scalar(expected));
  const std::string resolved = named.is_absolute() || !node.origin()->is_file
                                   ? named.string()
                                   : (std::filesystem::path(node.origin()->name).parent_path() / named).string();
  if (node.provenance()) node.provenance()->note_resolved_path(node.path(), std::filesystem::absolute(resolved).string());
  return resolved;
}

namespace {

// docs/physics.md section 13: one profile of the combined surface, or one per face of the film
// (the faces are independent, so their spectral moments add).
AsperityParameters summits_from_profiles(const Node& profile, const Scene& scene, std::vector<std::string>& warnings) {
  std::vector<Node> files;
  if (profile.yaml().IsSequence()) {
    files = profile.list("one profile file of the combined surface, or a list of two, one per face");
    if (files.empty() || files.size() > 2)
      profile.fail(fmt::format("{}: a list of {} files; give one profile of the combined surface or two, "
                               "one per face of the film", profile.path(), files.size()));
  } else {
    files.push_back(profile);
  }
  ProfileEstimate estimate;
  SpectralMoments moments;
  for (const Node& file : files) {
    const std::string path = named_file_path(file, "the path of a roughness profile file (CSV)");
    const RoughnessProfile heights = read_roughness_profile(path);
    try {
      moments = combined(moments, spectral_moments(heights.heights, heights.spacing));
    } catch (const std::invalid_argument& e) {
      file.fail(fmt::format("{}: the profile '{}': {}", file.path(), path, e.what()));
    }
    estimate.files.push_back(path);
    estimate.spacings.push_back(heights.spacing);
    estimate.samples.push_back(heights.heights.size());
  }
  estimate.m0 = moments.m0;
  estimate.m2 = moments.m2;
  estimate.m4 = moments.m4;
  estimate.bandwidth = moments.bandwidth();
  SummitStatistics summits;
  try {
    summits = mccool_summits(moments);
  } catch (const std::invalid_argument& e) {
    profile.fail(fmt::format("{}: {} (McCool's relations need a random rough surface)", profile.path(), e.what()));
  }
  const auto check = [&](double value, const Range& range, std::string_view what) {
    if (!range.contains(value))
      profile.fail(fmt::format("{}: the profile gives {} {:.4g}, outside what the contact model represents "
                               "({}{}); is the unit in the file's header right?",
                               profile.path(), what, value, range.describe(),
                               range.reason.empty() ? "" : fmt::format(": {}", range.reason)));
  };
  check(summits.radius, bounds::summit_radius, "a summit radius (m)");
  check(summits.sigma, bounds::roughness, "a summit-height standard deviation (m)");
  check(summits.density, bounds::summit_density, "a summit density (1/m^2)");
  if (estimate.bandwidth < mccool_min_bandwidth)
    warnings.push_back(fmt::format(
        "{}: the profile's bandwidth parameter is {:.3g}, below the {} McCool's relations were validated "
        "for: its summit statistics are rough estimates (a longer trace, or a finer sampling, widens the band)",
        profile.path(), estimate.bandwidth, mccool_min_bandwidth));
  const double profile_rq = std::sqrt(moments.m0);
  const double scene_rq = std::hypot(scene.carrier.roughness.rq, scene.washer.roughness.rq);
  if (std::abs(profile_rq - scene_rq) > 0.1 * scene_rq)
    warnings.push_back(fmt::format(
        "{}: the profile's combined Rq is {:.4g} m, the surfaces' Rq combine to {:.4g} m: the flow factors "
        "use the surfaces', the contact the profile's", profile.path(), profile_rq, scene_rq));
  AsperityParameters a;
  a.summit_radius = summits.radius;
  a.summit_sigma = summits.sigma;
  a.summit_density = summits.density;
  a.eta_r_sigma = a.summit_density * a.summit_radius * a.summit_sigma;
  a.profile = std::move(estimate);
  return a;
}

// Summit statistics of the carrier-washer pair (film 1, the paper's sliding film). The
// defaults follow docs/physics.md section 4: sigma_s = the combined sigma, eta = eta_R_sigma/(R sigma_s).
AsperityParameters read_asperities(const MapReader& surfaces, Scene& scene) {
  const MapReader summits = surfaces.map(
      "asperities", {"summit_radius", "summit_sigma", "summit_density", "eta_R_sigma", "profile"});
  if (const std::optional<Node> profile = summits.find("profile")) {
    summits.restrict_to({"profile"}, "with a profile");
    return summits_from_profiles(*profile, scene, scene.warnings);
  }
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
  out.carrier.roughness = read_roughness(surfaces, "carrier", out.effects);
  out.washer.roughness = read_roughness(surfaces, "washer", out.effects);
  out.gear.roughness = read_roughness(surfaces, "gear", out.effects);
  out.asperities = read_asperities(surfaces, out);
}

}  // namespace twb::scene_io

namespace twb {

std::array<double, 2> film_radii(const Scene& scene, int film) {
  if (film == 1) return {scene.washer.inner_radius, scene.washer.outer_radius};
  return {std::max(scene.washer.inner_radius, scene.gear.inner_radius),
          std::min(scene.washer.outer_radius, scene.gear.outer_radius)};
}

}  // namespace twb
