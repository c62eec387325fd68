// The scene file's top level: which sections exist, in the order the physics needs them
// (the operating limits depend on the lubricant's viscosity law, the asperity defaults
// on the surfaces).
#include "scene_sections.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "scene_names.h"
#include "twb/scene/scene_inputs.h"

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

// A sensitivity study's parameters name inputs of this scene.
void check_study_parameters(const MapReader& scene, const Scene& out) {
  if (out.study.parameters.empty()) return;
  const MapReader study = scene.map("study", {std::begin(kStudyKeys), std::end(kStudyKeys)});
  const std::vector<Node> items = study.get("parameters", "").list("");
  for (const Node& item : items) {
    try {
      scene_input(out, item.yaml().Scalar());
    } catch (const std::invalid_argument& e) {
      item.fail(fmt::format("{}: {}", item.path(), e.what()));
    }
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
  read_numerics(scene, out);
  read_grooves(scene, out);
  check_groove_parameter(scene, out);
  YAML::Emitter written;
  written << root.yaml();
  out.written = written.c_str();
  out.inputs = inputs_read(*root.provenance());
  check_study_parameters(scene, out);
  return out;
}

}  // namespace twb::scene_io
