// The scene file's top level: which sections exist, in the order the physics needs them
// (the operating limits depend on the lubricant's viscosity law, the asperity defaults
// on the surfaces).
#include "scene_sections.h"
#include "studies/study_section.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "scene_names.h"
#include "tree_path.h"
#include "twb/error_family.h"
#include "twb/input_error.h"
#include "twb/scene/scene_inputs.h"
#include "twb/scene/scene_loader.h"

namespace twb::scene_io {

namespace {

// Each quantity read in the bearing's sections, once (a reader that reads a value again,
// such as the grooves' check, reads the same number).
std::vector<SceneInput> inputs_read(const Provenance& provenance) {
  std::vector<SceneInput> out;
  for (const Provenance::ReadQuantity& q : provenance.quantities_read()) {
    if (!is_bearing_input_path(q.path)) continue;
    const auto seen = std::find_if(out.begin(), out.end(), [&](const SceneInput& in) { return in.path == q.path; });
    if (seen == out.end()) out.push_back({q.path, q.value, std::string(q.unit)});
  }
  return out;
}

// The tree as read, with every file a value names as the reader resolved it.
std::string written_tree(const Node& root) {
  YAML::Node tree = YAML::Clone(root.yaml());
  for (const auto& [path, resolved] : root.provenance()->resolved_paths())
    if (std::optional<YAML::Node> node = node_at(tree, path)) *node = resolved;
  YAML::Emitter written;
  written << tree;
  return written.c_str();
}

}  // namespace

// Why the scene refuses an input at `value`, if it does: the scene read again with it,
// as a point study (a trial must not check a study's parameters or axis again).
std::optional<InputError> refused(const Scene& out, const SceneInput& input, double value) {
  // As a study will set it (with_inputs: a face's Ra carried along with its Rq).
  try {
    const std::pair<std::string, double> set[] = {{input.path, value}};
    with_inputs(out, set, true);
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

namespace {

// A sensitivity study's parameters name inputs of this scene.
void check_study_parameters(const MapReader& scene, const Scene& out) {
  const auto* sensitivity = std::get_if<SensitivitySettings>(&out.study.settings);
  if (!sensitivity || sensitivity->parameters.empty()) return;
  const MapReader study = scene.map("study", {std::begin(kStudyKeys), std::end(kStudyKeys)});
  const std::vector<Node> items = study.get("parameters", "").list("");
  for (const Node& item : items) {
    const std::string path = item.yaml().Scalar();
    if (const std::string why = stepwise_input(path); !why.empty())
      item.fail(fmt::format("{}: {}; leave it out (a map over it shows its steps: type: distress_map)", item.path(),
                            why));
    SceneInput input;
    try {
      input = scene_input(out, path);
    } catch (const std::invalid_argument& e) {
      item.fail(fmt::format("{}: {}", item.path(), e.what()));
    }
    const bool written = std::any_of(out.inputs.begin(), out.inputs.end(), [&](const SceneInput& in) { return in.path == path; });
    if (written) continue;
    // A default the scene resolved to may be one derived from what the file gives (the
    // summit density of an eta_R_sigma, a data sheet's Roelands constants), which the
    // reader refuses beside it: tried once here rather than at every difference step.
    if (const std::optional<InputError> e = refused(out, input, input.value))
      item.fail(fmt::format("{}: '{}' cannot be set in this scene: {}", item.path(), path, e->message()));
  }
}

// A map's or family's axes over inputs' scene paths: each path names an input other than
// the load and the speed (the search's and the map's own axes), and every value, in the
// input's unit, makes a scene the reader accepts (tried once each, as a point study).
void check_input_axis(const MapReader& scene, Scene& out) {
  const std::span<MapAxis> axes = out.study.axes();
  bool any = false;
  for (const MapAxis& a : axes) any = any || a.parameter == MapParameter::scene_input;
  if (!any) return;
  const std::vector<MapReader> nodes = axis_nodes(scene);
  if (nodes.size() != axes.size()) throw InternalError("check_input_axis: the axes and their nodes differ");
  for (std::size_t k = 0; k < axes.size(); ++k) {
    MapAxis& s = axes[k];
    if (s.parameter != MapParameter::scene_input) continue;
    const MapReader& axis = nodes[k];
    const Node name = axis.get("name", "");
    if (s.path == "operating.load" || s.path == "operating.speed")
      name.fail(fmt::format("{}: {} is an axis of every search already ({}); a map's parameter is another input",
                            name.path(), s.path,
                            s.path == "operating.load" ? "the load it continues in" : "study.speeds"));
    SceneInput input;
    try {
      input = scene_input(out, s.path);
    } catch (const std::invalid_argument& e) {
      name.fail(fmt::format("{}: {}", name.path(), e.what()));
    }
    s.unit = input.unit;
    for (const Node& item : axis.get("values", "").list("")) {
      const double value = item.quantity(si::of_symbol(input.unit), Range{});
      if (const std::optional<InputError> e = refused(out, input, value))
        item.fail(fmt::format("{}: {}", item.path(), e->message()));
      s.values.push_back(value);
    }
  }
}

// A body whose modulus data begin above the ambient takes its first point's modulus down
// to the ambient (docs/physics.md section 23): said once, as the scene is read, since a
// cold start or a cool body sits there.
void warn_of_modulus_data_above_ambient(Scene& scene) {
  const std::pair<const char*, const Material*> bodies[] = {
      {"carrier", &scene.carrier.material}, {"washer", &scene.washer.material}, {"gear", &scene.gear.material}};
  for (const auto& [body, material] : bodies) {
    if (material->modulus_by_temperature.empty()) continue;
    const double first = material->modulus_by_temperature.front().temperature;
    if (scene.operating.ambient < first)
      scene.warnings.push_back(fmt::format(
          "materials.{}.modulus_by_temperature begins at {:.1f} degC, above the ambient {:.1f} degC: below its "
          "first point the modulus is held at that point's",
          body, first - 273.15, scene.operating.ambient - 273.15));
  }
}

}  // namespace

Scene read_scene(const Node& root) {
  const MapReader scene(root, {"effects", "geometry", "materials", "surfaces", "lubricant",
                               "limits", "operating", "friction", "mesh", "solver", "study", "output"});
  Scene out;
  out.effects = read_effects(scene);
  read_bodies(scene, out);
  read_operation(scene, out);
  warn_of_modulus_data_above_ambient(out);
  read_numerics(scene, out);
  read_grooves(scene, out);
  check_groove_parameter(scene, out);
  out.written = written_tree(root);
  out.inputs = inputs_read(*root.provenance());
  check_study_parameters(scene, out);
  check_input_axis(scene, out);
  if (const auto read_after_inputs = study_section(out.study.type()).read_after_inputs) read_after_inputs(scene, out);
  return out;
}

}  // namespace twb::scene_io
