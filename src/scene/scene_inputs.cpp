#include "twb/scene/scene_inputs.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "scene/key_suggestion.h"
#include "scene/quantity.h"
#include "scene/tree_path.h"
#include "twb/scene/scene_loader.h"

namespace twb {

namespace {

constexpr std::string_view kInputSections[] = {"geometry.", "materials.", "surfaces.", "lubricant.",
                                               "limits.",   "operating.", "friction."};

// The resolved scene's number at `path`, if it writes one there.
std::optional<SceneInput> resolved_input(const Scene& scene, const std::string& path) {
  const std::optional<YAML::Node> node = scene_io::node_at(YAML::Load(describe_scene(scene)), path);
  if (!node || !node->IsScalar()) return std::nullopt;
  const std::string text = node->Scalar();
  if (text.find_first_of(" \t") == std::string::npos) {
    try {
      return SceneInput{path, to_si(text, si::dimensionless), "1"};
    } catch (const QuantityError&) {
      return std::nullopt;  // a name (an enum value), not a number
    }
  }
  for (const SiUnit* unit : si::all) {
    try {
      return SceneInput{path, to_si(text, *unit), std::string(unit->symbol)};
    } catch (const QuantityError&) {
    }
  }
  return std::nullopt;
}

}  // namespace

bool is_bearing_input_path(std::string_view path) {
  if (path.find('[') != std::string_view::npos) return false;
  return std::any_of(std::begin(kInputSections), std::end(kInputSections),
                     [&](std::string_view section) { return path.starts_with(section); });
}

std::string stepwise_input(std::string_view path) {
  constexpr std::string_view grooves = "geometry.washer.grooves.";
  if (!path.starts_with(grooves) || path.ends_with(".depth")) return {};
  return fmt::format("'{}' is placed on the grid's cells and node lines, so the bearing changes with it by steps "
                     "that have no derivative (the grooves' and lands' depths are smooth inputs)",
                     path);
}

SceneInput scene_input(const Scene& scene, const std::string& path) {
  for (const SceneInput& in : scene.inputs)
    if (in.path == path) return in;
  if (is_bearing_input_path(path))
    if (std::optional<SceneInput> resolved = resolved_input(scene, path)) return *resolved;
  std::vector<std::string_view> paths;
  for (const SceneInput& in : scene.inputs) paths.push_back(in.path);
  const std::string why =
      is_bearing_input_path(path) ? "names no number of the bearing the scene writes or defaults"
      : path.find('[') != std::string::npos
          ? "is an item of a list, which is no input (a viscosity table's points, a map's values)"
          : "is not in the bearing's sections (geometry, materials, surfaces, lubricant, limits, operating, friction)";
  throw std::invalid_argument(fmt::format("'{}' {}{}", path, why,
                                          scene_io::allowed_after(scene_io::closest_match(path, paths), paths)));
}

std::string input_override(const std::string& path, double value, std::string_view unit) {
  return unit == "1" ? fmt::format("{}={:.17g}", path, value) : fmt::format("{}={:.17g} {}", path, value, unit);
}

namespace {

// A face's Rq changed (surfaces.<face>.Rq): its Ra, scaled by the same factor, where Ra
// is not set too. Ra enters no equation (σ is Rq), but it may not exceed Rq, so an
// uncertain or differenced Rq carries the face's Ra along at the face's own Ra/Rq, the
// texture the scene gives it (docs/physics.md section 4). Not the other way round: Ra set
// alone changes nothing the model reads (its derivatives are nought), and above Rq it is
// refused. Empty for every other input.
std::optional<std::string> roughness_companion(const Scene& scene, const std::string& path, double value,
                                               std::span<const std::pair<std::string, double>> values) {
  if (!path.starts_with("surfaces.") || !path.ends_with(".Rq")) return std::nullopt;
  const std::string other = path.substr(0, path.size() - 2) + "Ra";  // "surfaces.washer.Ra"
  if (std::any_of(values.begin(), values.end(), [&](const auto& v) { return v.first == other; })) return std::nullopt;
  const SceneInput now = scene_input(scene, path), companion = scene_input(scene, other);
  if (now.value <= 0.0) return std::nullopt;
  return input_override(other, companion.value * value / now.value, companion.unit);
}

}  // namespace

Scene with_inputs(const Scene& scene, std::span<const std::pair<std::string, double>> values, bool keep_study) {
  std::vector<std::string> overrides;
  for (const auto& [path, value] : values) {
    overrides.push_back(input_override(path, value, scene_input(scene, path).unit));
    if (std::optional<std::string> companion = roughness_companion(scene, path, value, values))
      overrides.push_back(std::move(*companion));
  }
  if (keep_study) overrides.push_back("study={type: point}");
  Scene out = load_scene_text(scene.written, scene.source, overrides);
  if (keep_study) out.study = scene.study;
  out.worn = scene.worn;
  return out;
}

Scene bearing_scene(const Scene& scene) {
  Scene out = load_scene_text(scene.written, scene.source, {"study={type: point}"});
  out.worn = scene.worn;
  return out;
}

}  // namespace twb
