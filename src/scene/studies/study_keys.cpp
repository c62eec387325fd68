// The keys more than one study type reads and writes: load ranges and grids, speeds, map
// axes, the bracket, the error bar's estimate and tolerance.
#include "scene/studies/study_keys.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include <fmt/format.h>

#include "scene/physical_bounds.h"
#include "scene/scene_names.h"
#include "scene/scene_sections.h"

namespace twb::scene_io {

void read_load_range(const MapReader& study, LoadRange& loads, std::string_view end_relation) {
  loads.start = study.quantity("load_start", si::force, bounds::load);
  loads.end = study.quantity("load_end", si::force, bounds::load);
  if (loads.end <= loads.start) {
    const Node node = study.get("load_end", "");
    node.fail(fmt::format("{}: '{}' must be greater than load_start '{}'{}", node.path(), node.yaml().Scalar(),
                          study.get("load_start", "").yaml().Scalar(), end_relation));
  }
}

// A dimensionless study key that is a number in `range` or `none` (0), left at `value`
// where absent.
void read_number_or_none(const MapReader& study, std::string_view key, const Range& range, double& value) {
  if (!study.has(key)) return;
  const Node node = study.get(key, "");
  value = node.yaml().IsScalar() && node.yaml().Scalar() == "none" ? 0.0
                                                                  : study.quantity(key, si::dimensionless, range);
}

// study.tolerance: a relative accuracy ("1 %", 0.01) or none; refused beside
// error_estimate: none, which asks for no refined mesh at all.
void read_tolerance(const MapReader& study, ErrorBarSettings& bars) {
  if (study.has("tolerance") && bars.estimate == ErrorEstimate::none) {
    const Node node = study.get("tolerance", "");
    node.fail(fmt::format("{}: a tolerance refines the mesh until each failure load's error bar meets it, and "
                          "error_estimate: none asks for no error bar; leave one of them out",
                          node.path()));
  }
  read_number_or_none(study, "tolerance",
                      Range{.low = 0.0, .low_open = true, .high = 0.5,
                            .reason = "the relative accuracy wanted of each failure load, e.g. '1 %' or 0.01, or none"},
                      bars.tolerance);
}

double read_bracket_width(const MapReader& study, double fallback) {
  return study.quantity("bracket_width", si::dimensionless,
                        Range{.low = 0.0, .low_open = true, .high = 0.1,
                              .reason = "the relative width of the distress bracket, e.g. 0.002"},
                        fallback);
}

namespace {

// One axis: `{name: friction_coefficient, values: [0.05, 0.1]}`, or an input's scene path
// for a name, whose values are read once every input is known (check_input_axis).
MapAxis read_map_axis(const MapReader& p, const Scene& scene) {
  MapAxis axis;
  const Node name = p.get("name", "friction_coefficient, gear_tilt, roughness, groove_count, groove_width, "
                                  "groove_depth, or an input's scene path such as geometry.gear.tilt");
  // A scene path has a dot; no named parameter does.
  if (name.yaml().IsScalar() && name.yaml().Scalar().find('.') != std::string::npos) {
    axis.parameter = MapParameter::scene_input;
    axis.path = name.yaml().Scalar();
    const Node values = p.get("values", "a list of values, e.g. [1 mrad, 2 mrad]");
    if (values.list("a list of values, e.g. [1 mrad, 2 mrad]").empty())
      values.fail(fmt::format("{}: the list is empty; give at least one value", values.path()));
    return axis;
  }
  axis.parameter = kMapParameters.values[name.choice(kMapParameters.names)];
  const Node values = p.get("values", "a list of values, e.g. [0.05, 0.1, 0.2]");
  const std::vector<Node> items = values.list("a list of values, e.g. [0.05, 0.1, 0.2]");
  if (items.empty())
    values.fail(fmt::format("{}: the list is empty; give at least one value", values.path()));
  // A groove's values are checked against the grooves once those are read
  // (check_groove_parameter).
  for (const Node& item : items) {
    switch (axis.parameter) {
      case MapParameter::friction_coefficient:
        axis.values.push_back(item.quantity(si::dimensionless, bounds::friction_coefficient));
        break;
      case MapParameter::gear_tilt:
        axis.values.push_back(item.quantity(si::angle, bounds::tilt));
        break;
      case MapParameter::roughness:
        axis.values.push_back(item.quantity(si::length, bounds::roughness));
        break;
      case MapParameter::groove_count:
        axis.values.push_back(item.integer(1, 360, "grooves round the face"));
        break;
      case MapParameter::groove_width:
        axis.values.push_back(groove_angle(item, 0.5 * (scene.washer.inner_radius + scene.washer.outer_radius)));
        break;
      case MapParameter::groove_depth:
        axis.values.push_back(item.quantity(si::length, bounds::groove_depth));
        break;
      case MapParameter::none:
      case MapParameter::scene_input:
        break;
    }
  }
  if (axis.parameter == MapParameter::friction_coefficient && scene.friction.law != FrictionLaw::constant)
    name.fail(fmt::format("{}: friction_coefficient varies the constant friction law's coefficient; "
                          "set friction.law: constant",
                          name.path()));
  return axis;
}

}  // namespace

// The scene path (or, for the roughness, every path under it) a named parameter sets:
// a grid may not vary one input twice, by its name and by its path.
std::string_view set_by(MapParameter p) {
  switch (p) {
    case MapParameter::friction_coefficient: return "friction.coefficient";
    case MapParameter::gear_tilt: return "geometry.gear.tilt";
    case MapParameter::roughness: return "surfaces.";
    case MapParameter::groove_count: return "geometry.washer.grooves.count";
    case MapParameter::groove_width: return "geometry.washer.grooves.width";
    case MapParameter::groove_depth: return "geometry.washer.grooves.depth";
    case MapParameter::none:
    case MapParameter::scene_input: break;
  }
  return {};
}

namespace {

bool same_input(const MapAxis& a, const MapAxis& b) {
  const bool a_path = a.parameter == MapParameter::scene_input, b_path = b.parameter == MapParameter::scene_input;
  if (a_path && b_path) return a.path == b.path;
  if (!a_path && !b_path) return a.parameter == b.parameter;
  const MapAxis& named = a_path ? b : a;
  const std::string& path = a_path ? a.path : b.path;
  const std::string_view sets = set_by(named.parameter);
  return sets.ends_with('.') ? path.starts_with(sets) : path == sets;
}

}  // namespace

// The axes of a distress map or load sweep besides the speed: `parameter: {name: ...,
// values: [...]}`, or a list of such maps, a grid of every combination; a distress
// curve's family: `family: {...}`, one axis.
void read_map_axes(const MapReader& study, std::vector<MapAxis>& axes, const Scene& scene, const char* key) {
  if (!study.has(key)) return;
  const Node node = study.get(key, "");
  if (!(std::string_view(key) == "parameter" && node.yaml().IsSequence())) {
    axes.push_back(read_map_axis(study.map(key, {"name", "values"}), scene));
    return;
  }
  const std::vector<Node> items = node.list("a list of axes, each {name: ..., values: [...]}");
  if (items.empty())
    node.fail(fmt::format("{}: the list is empty; give at least one axis, e.g. [{{name: friction_coefficient, "
                          "values: [0.05, 0.1]}}]",
                          node.path()));
  for (const Node& item : items) {
    const MapReader p(item, {"name", "values"});
    MapAxis axis = read_map_axis(p, scene);
    for (const MapAxis& before : axes)
      if (same_input(before, axis)) {
        const Node name = p.get("name", "");
        const bool twice = before.parameter == axis.parameter && before.path == axis.path;
        name.fail(twice ? fmt::format("{}: {} is an axis of this grid already; each axis varies another input",
                                      name.path(), name.yaml().Scalar())
                        : fmt::format("{}: {} varies what the axis {} varies already; each axis varies another input",
                                      name.path(), name.yaml().Scalar(),
                                      before.parameter == MapParameter::scene_input
                                          ? before.path
                                          : std::string(kMapParameters.name(before.parameter))));
      }
    axes.push_back(std::move(axis));
  }
}

// Whether a speed was written in revolutions per minute ("3000 rpm", "3 krpm",
// "50 r/min"): what the figures then show (run.json's speed_unit).
bool given_in_rpm(const Node& speed) {
  if (!speed.yaml().IsScalar()) return false;
  std::string text = speed.yaml().Scalar();
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text.ends_with("rpm") || text.ends_with("r/min") || text.ends_with("rev/min");
}

// The speeds of one search each: `speeds: [136 rad/s, 545 rad/s]`.
void read_speeds(const MapReader& study, std::vector<double>& speeds, bool& in_rpm) {
  const Node list = study.get("speeds", "a list of speeds, e.g. [136 rad/s, 545 rad/s]");
  const std::vector<Node> items = list.list("speeds, e.g. [136 rad/s, 545 rad/s]");
  if (items.empty())
    list.fail(fmt::format("{}: the list is empty; give at least one speed, e.g. "
                          "[136 rad/s, 545 rad/s]",
                          list.path()));
  for (const Node& speed : items) speeds.push_back(speed.quantity(si::angular_speed, bounds::speed));
  in_rpm = std::all_of(items.begin(), items.end(), [](const Node& n) { return given_in_rpm(n); });
}

// A load grid (load_sweep, sliding_choice): the range, its number of loads, and the
// speeds, operating.speed when the study names none.
void read_load_grid(const MapReader& study, Scene& out, LoadGrid& grid) {
  read_load_range(study, grid.loads, "");
  grid.load_steps = study.get("load_steps", "a whole number in [2, 10000]")
                        .integer(2, 10000, "the number of loads, both ends included");
  if (study.has("speeds"))
    read_speeds(study, grid.speeds, out.study.speeds_in_rpm);
  else
    grid.speeds = {out.operating.speed};
  grid.bracket_width = read_bracket_width(study, grid.bracket_width);
}

// every_state refines each state of a sweep; a point's one state has its bar with
// richardson, and a distress curve reports folds and crossings, not a sweep's states.
void refuse_every_state(const MapReader& study, const ErrorBarSettings& bars, const char* type) {
  if (bars.estimate != ErrorEstimate::every_state) return;
  const Node node = study.get("error_estimate", "");
  node.fail(fmt::format("{}: every_state (an error bar on every state of a sweep) is for load_sweep and "
                        "distress_map; with type: {} use richardson or none",
                        node.path(), type));
}

// The nodes of a study's axes (its parameter's or family's maps, in order).
std::vector<MapReader> axis_nodes_of(const MapReader& study) {
  std::vector<MapReader> out;
  const char* key = study.has("family") ? "family" : "parameter";
  if (!study.has(key)) return out;
  const Node node = study.get(key, "");
  if (node.yaml().IsSequence())
    for (const Node& item : node.list("")) out.emplace_back(item, std::vector<std::string_view>{"name", "values"});
  else if (node.yaml().IsMap())
    out.push_back(study.map(key, {"name", "values"}));
  return out;  // none for a distress curve's own parameter (a name)
}


void write_load_range(SceneText& w, const LoadRange& loads) {
  w.entry(1, "load_start", quantity(loads.start, "N"));
  w.entry(1, "load_end", quantity(loads.end, "N"));
}

void write_speeds(SceneText& w, std::span<const double> speeds) {
  std::string text;
  for (double speed : speeds) text += (text.empty() ? "" : ", ") + quantity(speed, "rad/s");
  w.entry(1, "speeds", fmt::format("[{}]", text));
}

namespace {

// An axis's name and its values in the scene's spelling.
std::pair<std::string, std::string> axis_text(const MapAxis& a) {
  const char* unit = a.parameter == MapParameter::gear_tilt || a.parameter == MapParameter::groove_width ? "rad"
                     : a.parameter == MapParameter::roughness || a.parameter == MapParameter::groove_depth ? "m"
                                                                                                           : "1";
  std::string values;
  for (double v : a.values)
    values += (values.empty() ? "" : ", ") +
              (a.parameter == MapParameter::groove_count ? fmt::format("{}", int(v))
               : a.parameter == MapParameter::scene_input ? quantity(v, a.unit)
                                                          : quantity(v, unit));
  return {a.parameter == MapParameter::scene_input ? a.path : std::string(kMapParameters.name(a.parameter)),
          fmt::format("[{}]", values)};
}

}  // namespace

void write_axes(SceneText& w, std::span<const MapAxis> axes, const char* key) {
  if (axes.empty()) return;
  w.line(1, std::string(key) + ":");
  if (axes.size() == 1) {
    const auto [name, values] = axis_text(axes.front());
    w.entry(2, "name", name);
    w.entry(2, "values", values);
    return;
  }
  for (const MapAxis& a : axes) {
    const auto [name, values] = axis_text(a);
    w.line(2, fmt::format("- name: {}", name));
    w.entry(3, "values", values);
  }
}

void write_load_grid(SceneText& w, const LoadGrid& grid, std::span<const MapAxis> axes) {
  write_load_range(w, grid.loads);
  w.entry(1, "load_steps", fmt::format("{}", grid.load_steps));
  write_speeds(w, grid.speeds);
  write_axes(w, axes, "parameter");
  w.entry(1, "bracket_width", quantity(grid.bracket_width, "1"));
}

void write_error_estimate(SceneText& w, const ErrorBarSettings& bars) {
  w.entry(1, "error_estimate", std::string(kErrorEstimates.name(bars.estimate)));
}

void write_tolerance(SceneText& w, const ErrorBarSettings& bars) {
  if (bars.estimate != ErrorEstimate::none)
    w.entry(1, "tolerance", bars.tolerance > 0.0 ? quantity(bars.tolerance, "1") : std::string("none"));
}

void write_schedule(SceneText& w, const DutyCycleSettings& cycle) {
  w.line(1, "schedule:");
  for (const SchedulePoint& p : cycle.schedule)
    w.line(2, fmt::format("- {{t: {}, load: {}, speed: {}, ambient: {}, tilt: {}}}", quantity(p.time, "s"),
                          quantity(p.load, "N"), quantity(p.speed, "rad/s"), quantity(p.ambient, "K"),
                          quantity(p.tilt, "rad")));
}

}  // namespace twb::scene_io
