// The washer's face grooves and the shapes of its lands (docs/physics.md section 14):
// read last, because they round the mesh so that every edge lies on a node line, and
// because the face they are cut in must be at rest in the load frame.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "physical_bounds.h"
#include "scene_names.h"
#include "scene_sections.h"
#include "quantity.h"
#include "twb/error_family.h"

namespace twb::scene_io {
namespace {

inline constexpr EnumNames<int, 2> kGroovedFaces{{"film_1", "film_2"}, {1, 2}};

inline constexpr Range land_depth{.low = 1e-8, .high = 1e-3, .reason = "a taper or step from 10 nm to 1 mm deep"};
inline constexpr Range land_fraction{.low = 0.0, .low_open = true, .high = 1.0,
                                     .reason = "a share of the land's angle, above 0 and at most 1"};

Land read_land(const MapReader& grooves) {
  Land land;
  if (!grooves.has("land")) return land;
  const MapReader shape = grooves.map("land", {"taper", "step"});
  const std::vector<std::string> keys = shape.keys();
  if (keys.size() != 1) {
    const Node node = grooves.get("land", "");
    node.fail(fmt::format("{}: expected one shape, taper: {{depth, fraction}} or step: {{depth, fraction}}; got {}",
                          node.path(), keys.empty() ? "none" : fmt::format("{}", fmt::join(keys, " and "))));
  }
  land.shape = keys.front() == "taper" ? LandShape::taper : LandShape::step;
  const MapReader inlet = shape.map(keys.front(), {"depth", "fraction"});
  land.depth = inlet.quantity("depth", si::length, land_depth);
  land.fraction = inlet.quantity("fraction", si::dimensionless, land_fraction);
  return land;
}

// A groove closed short of one rim: `closed_at` the dam's radius, `open_at` the rim the
// groove runs from (the bore by default, where a transmission's oil comes from).
std::optional<GrooveDam> read_dam(const MapReader& grooves) {
  if (!grooves.has("closed_at")) {
    if (grooves.has("open_at")) {
      const Node node = grooves.get("open_at", "");
      node.fail(fmt::format("{}: a groove open at one rim needs the radius it is closed at (closed_at: e.g. 22 mm); "
                            "without closed_at every groove runs from rim to rim",
                            node.path()));
    }
    return std::nullopt;
  }
  GrooveDam dam;
  dam.written_radius = grooves.quantity("closed_at", si::length, bounds::dam_radius);
  dam.open_at = read_choice(grooves, "open_at", kGrooveOpenings, GrooveOpening::inner_radius);
  return dam;
}

// The scene's `lubricant.supply.at`, where a supply into the grooves is refused.
[[noreturn]] void refuse_groove_supply(const MapReader& scene, const std::string& why) {
  const MapReader oil = scene.map("lubricant", {std::begin(kLubricantKeys), std::end(kLubricantKeys)});
  const Node at = oil.map("supply", {std::begin(kSupplyKeys), std::end(kSupplyKeys)}).get("at", "");
  at.fail(fmt::format("{}: oil supplied at '{}' needs {}; feed the bore alone with at: inner_radius", at.path(),
                      at.yaml().Scalar(), why));
}

}  // namespace

// A bare number would be neither a length nor an angle for sure.
double groove_angle(const Node& node, double mean_radius) {
  const std::string text = node.yaml().Scalar();
  if (std::none_of(text.begin(), text.end(), [](unsigned char c) { return std::isalpha(c); }))
    node.fail(fmt::format("{}: '{}' has no unit; give the groove's width as a length (e.g. 2 mm, at the mean radius) "
                          "or an angle (e.g. 10 deg)",
                          node.path(), text));
  try {
    (void)to_si(text, si::length);  // a length, or else an angle
  } catch (const QuantityError&) {
    return node.quantity(si::angle, {.low = 0.0, .low_open = true, .high = 2 * std::numbers::pi});
  }
  // A length is the width at the mean radius, bounded as the angle is.
  const double circumference = 2 * std::numbers::pi * mean_radius;
  return node.quantity(si::length,
                       {.low = 0.0, .low_open = true, .high = circumference,
                        .reason = "a groove is wider than nothing and at most the circumference at the mean radius"}) /
         mean_radius;
}

namespace {

bool varies_grooves(MapParameter p) {
  return p == MapParameter::groove_count || p == MapParameter::groove_width || p == MapParameter::groove_depth;
}

}  // namespace

void check_groove_parameter(const MapReader& scene, const Scene& out) {
  const std::span<const MapAxis> axes = out.study.axes();
  std::vector<std::size_t> groove_axes;
  for (std::size_t k = 0; k < axes.size(); ++k)
    if (varies_grooves(axes[k].parameter)) groove_axes.push_back(k);
  if (groove_axes.empty()) return;
  const std::vector<MapReader> nodes = axis_nodes(scene);
  if (nodes.size() != axes.size()) throw InternalError("check_groove_parameter: the axes and their nodes differ");
  if (!out.washer.grooves) {
    const Node name = nodes[groove_axes.front()].get("name", "");
    name.fail(fmt::format("{}: {} varies the washer's grooves, and the scene has none; give them in "
                          "geometry.washer.grooves",
                          name.path(), name.yaml().Scalar()));
  }
  // Every combination of the groove axes' values (a count and a width may fit alone and
  // not together), each placed in the axes' order, as the searches place them; a
  // combination that fails is refused at the value of the last axis it placed.
  std::vector<std::size_t> at(groove_axes.size(), 0), sizes;
  for (std::size_t k : groove_axes) sizes.push_back(axes[k].values.size());
  do {
    Scene trial = out;
    for (std::size_t g = 0; g < groove_axes.size(); ++g) {
      const MapAxis& axis = axes[groove_axes[g]];
      if (const std::optional<GroovesNotPlaced> not_placed = place_groove_parameter(trial, axis.parameter, axis.values[at[g]])) {
        const Node item = nodes[groove_axes[g]].get("values", "").list("")[at[g]];
        std::string with;
        for (std::size_t h = 0; h < g; ++h)
          with += fmt::format("{} {} = {:.6g}", h == 0 ? " (with" : ",",
                              kMapParameters.name(axes[groove_axes[h]].parameter), axes[groove_axes[h]].values[at[h]]);
        item.fail(fmt::format("{}: {}{}", item.path(), not_placed->why, with.empty() ? "" : with + ")"));
      }
    }
  } while (next_combination(at, sizes));
}

void read_grooves(const MapReader& scene, Scene& out) {
  const MapReader geometry(scene.get("geometry", ""), {"carrier", "washer", "gear"});
  const MapReader washer(geometry.get("washer", ""), {"inner_diameter", "outer_diameter", "thickness", "grooves"});
  const bool feeds_grooves = out.lubricant.supply && out.lubricant.supply->feeds_grooves();
  if (!washer.has("grooves")) {
    if (feeds_grooves) refuse_groove_supply(scene, "grooves to feed (geometry.washer.grooves)");
    return;
  }
  const MapReader grooves = washer.map("grooves", {"count", "width", "depth", "face", "land", "closed_at", "open_at"});
  // The relief is at rest in the load frame only where the washer is: with film 2
  // sliding the washer stays with the carrier (docs/physics.md section 14).
  if (out.operating.sliding != SlidingFilm::washer_gear) {
    const Node node = washer.get("grooves", "");
    node.fail(fmt::format("{}: a grooved washer needs operating.sliding: washer_gear (the washer at rest with the "
                          "carrier, its grooves at rest in the load frame); a washer turning with the gear "
                          "(carrier_washer) would carry its grooves round under the tilted films, which twb does "
                          "not model yet",
                          node.path()));
  }
  Grooves g;
  g.count = grooves.get("count", "the number of grooves round the face").integer(1, 360, "grooves round the face");
  g.film = read_choice(grooves, "face", kGroovedFaces, 2);
  if (feeds_grooves && g.film != 2)
    refuse_groove_supply(scene, "the grooves in the sliding film's face (face: film_2 with sliding: washer_gear)");
  g.depth = grooves.quantity("depth", si::length, bounds::groove_depth);
  g.land = read_land(grooves);
  g.closed_at = read_dam(grooves);
  g.width = groove_angle(grooves.get("width", "a length (e.g. 2 mm) or an angle (e.g. 10 deg)"),
                         0.5 * (out.washer.inner_radius + out.washer.outer_radius));
  if (const std::optional<GroovesNotPlaced> not_placed = place_grooves(out, g)) {
    const Node node = grooves.get(not_placed->key, "");
    node.fail(fmt::format("{}: {}", node.path(), not_placed->why));
  }
}

}  // namespace twb::scene_io

namespace twb {

std::optional<GroovesNotPlaced> place_grooves(Scene& scene, Grooves g) {
  g.written_width = g.width;
  const double pitch_angle = 2 * std::numbers::pi / g.count;
  if (!(g.width < pitch_angle))
    return GroovesNotPlaced{"width", fmt::format("{} grooves {:.4g} deg wide leave no land between them: the pitch "
                                                 "is {:.4g} deg (360 deg / count), and a groove must be narrower",
                                                 g.count, g.width * 180 / std::numbers::pi,
                                                 pitch_angle * 180 / std::numbers::pi)};
  if (!(g.depth < scene.washer.thickness))
    return GroovesNotPlaced{"depth", fmt::format("a groove {:.4g} mm deep would cut through the washer, {:.4g} mm "
                                                 "thick; it must be shallower than the washer",
                                                 g.depth * 1e3, scene.washer.thickness * 1e3)};
  // Every edge on a node line: a whole number of cells per groove pitch, and at least
  // one cell for the groove, the land, and a shaped inlet and the flat rest after a step.
  MeshSettings& mesh = scene.mesh;
  const int least_pitch = g.land.shape == LandShape::step ? 3 : 2;
  const int pitch = std::max(least_pitch, int(std::lround(double(mesh.circumferential_nodes) / g.count)));
  if (g.count * pitch > scene_io::bounds::kMostCircumferentialNodes)
    return GroovesNotPlaced{"count", fmt::format("{} grooves of at least {} cells each need {} circumferential nodes, "
                                                 "more than the {} a machine's memory allows",
                                                 g.count, pitch, g.count * pitch,
                                                 scene_io::bounds::kMostCircumferentialNodes)};
  mesh.circumferential_nodes = g.count * pitch;
  const double cell = 2 * std::numbers::pi / mesh.circumferential_nodes;
  const int land_least = g.land.shape == LandShape::step ? 2 : 1;
  g.cells = std::clamp(int(std::lround(g.width / cell)), 1, pitch - land_least);
  g.width = g.cells * cell;
  if (g.land.shape != LandShape::flat) {
    const int land_cells = pitch - g.cells;
    const int most = g.land.shape == LandShape::step ? land_cells - 1 : land_cells;
    g.land.fraction = double(std::clamp(int(std::lround(g.land.fraction * land_cells)), 1, most)) / land_cells;
  }
  if (g.closed_at) {
    // The dam on the grooved film's nearest radial node line, with at least one cell of
    // groove before it and one of dam after it.
    GrooveDam& dam = *g.closed_at;
    const std::array<double, 2> rims = film_radii(scene, g.film);
    const int last = mesh.radial_nodes - 1;
    const double dr = (rims[1] - rims[0]) / last;
    const bool inner = dam.open_at == GrooveOpening::inner_radius;
    if (!(dam.written_radius > rims[0] && dam.written_radius < rims[1]))
      return GroovesNotPlaced{"closed_at", fmt::format("a groove closed at {:.4g} mm would end off the grooved film, "
                                                       "which spans the radii {:.4g} to {:.4g} mm; the dam must lie "
                                                       "between them",
                                                       dam.written_radius * 1e3, rims[0] * 1e3, rims[1] * 1e3)};
    const int line = int(std::lround((dam.written_radius - rims[0]) / dr));
    if (line < 1 || line > last - 1)
      return GroovesNotPlaced{
          "closed_at",
          fmt::format("a groove open at the {} radius and closed at {:.4g} mm leaves {} on the grid of {} radial "
                      "nodes (cells of {:.4g} mm): move the dam at least a cell from the rims, or refine "
                      "mesh.radial_nodes",
                      inner ? "inner" : "outer", dam.written_radius * 1e3,
                      (line < 1) == inner ? "no cell of groove" : "no cell of dam", mesh.radial_nodes, dr * 1e3)};
    dam.line = line;
    dam.radius = rims[0] + line * dr;
  }
  scene.washer.grooves = g;
  return std::nullopt;
}

std::optional<GroovesNotPlaced> place_groove_parameter(Scene& scene, MapParameter p, double value) {
  if (!scene.washer.grooves) throw InternalError("place_groove_parameter: the scene has no grooves");
  Grooves g = *scene.washer.grooves;
  g.width = g.written_width;
  switch (p) {
    case MapParameter::groove_count: g.count = int(value); break;
    case MapParameter::groove_width: g.width = value; break;
    case MapParameter::groove_depth: g.depth = value; break;
    default: throw InternalError("place_groove_parameter: not a property of the grooves");
  }
  return place_grooves(scene, g);
}

}  // namespace twb
