#include "results/run_record.h"

#include "twb/results/scene_record.h"
#include "twb/scene/scene_loader.h"

#include <Eigen/Core>
#include <boost/version.hpp>
#include <fmt/format.h>
#include <klu.h>
#include <nlohmann/json.hpp>
#include <sundials/sundials_config.h>
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <optional>
#include <cmath>

namespace twb {

namespace {

using Json = nlohmann::ordered_json;

// A unit as the suffix of a key, as in the CSVs' column names: "W/(m K)" → "W_per_m_K",
// "1/m^2" → "per_m2", "rad/s" → "rad_s".
std::string unit_suffix(std::string unit) {
  if (unit == "rad/s") return "rad_s";
  if (unit.rfind("1/", 0) == 0) unit.replace(0, 2, "per ");
  std::string out;
  for (char c : unit) {
    if (c == '/') out += "_per_";
    else if (c == ' ') out += '_';
    else if (c != '(' && c != ')' && c != '^') out += c;
  }
  std::string squeezed;
  for (char c : out)
    if (!(c == '_' && !squeezed.empty() && squeezed.back() == '_')) squeezed += c;
  return squeezed;
}

// "0.0111 m" → (0.0111, "m"); a bare finite number → (value, ""); anything else: nullopt.
struct Quantity {
  double value;
  std::string unit;
};
std::optional<Quantity> quantity_of(const std::string& text) {
  const std::size_t space = text.find(' ');
  const std::string number = text.substr(0, space);
  double value = 0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (number.empty() || error != std::errc() || end != number.data() + number.size() || !std::isfinite(value))
    return std::nullopt;
  return Quantity{value, space == std::string::npos ? std::string() : text.substr(space + 1)};
}

// The described scene (values written "number unit", in SI) as JSON with numbers: a
// quantity's unit moves into its key ("thickness_m": 0.01), as in the CSVs; a list of
// quantities of one unit likewise ("speeds_rad_s": [545, 953]).
Json scene_json(const YAML::Node& node);

Json value_json(const YAML::Node& node, std::string& key) {
  if (node.IsScalar()) {
    const std::string& s = node.Scalar();
    if (s == "true" || s == "false") return s == "true";
    if (const auto q = quantity_of(s)) {
      if (!q->unit.empty()) key.append("_").append(unit_suffix(q->unit));
      return q->value;
    }
    return s;
  }
  if (node.IsSequence()) {
    Json list = Json::array();
    std::string unit;
    for (const YAML::Node& item : node) {
      std::string item_key;
      list.push_back(value_json(item, item_key));
      if (!item_key.empty()) unit = item_key;  // "_rad_s": the same for every item of a scene list
    }
    key += unit;
    return list;
  }
  if (node.IsMap()) return scene_json(node);
  return nullptr;
}

Json scene_json(const YAML::Node& node) {
  Json out = Json::object();
  for (const auto& entry : node) {
    std::string key = entry.first.as<std::string>();
    Json value = value_json(entry.second, key);
    out[key] = std::move(value);
  }
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> library_versions() {
  return {
      {"twb", TWB_VERSION},
      {"sundials", SUNDIALS_VERSION},
      {"klu", fmt::format("{}.{}.{}", KLU_MAIN_VERSION, KLU_SUB_VERSION, KLU_SUBSUB_VERSION)},
      {"eigen", fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"fmt", fmt::format("{}.{}.{}", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100)},
      {"boost", fmt::format("{}.{}.{}", BOOST_VERSION / 100000, BOOST_VERSION / 100 % 1000, BOOST_VERSION % 100)},
      {"nlohmann-json", fmt::format("{}.{}.{}", NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
                                    NLOHMANN_JSON_VERSION_PATCH)},
      {"yaml-cpp", "0.7"},
      {"udunits2", "2"},
      {"compiler", __VERSION__},
  };
}

std::string scene_record_json(const Scene& scene) { return scene_json(YAML::Load(describe_scene(scene))).dump(); }

std::string run_json(const std::string& scene_path, const std::string& resolved_scene_yaml,
                     const UnknownLayout& layout, const RunTimings& t, const std::string& outcome,
                     const std::string& speed_unit) {
  Json out;
  out["scene_file"] = scene_path;
  out["speed_unit"] = speed_unit;
  out["outcome"] = outcome;
  Json versions = Json::object();
  for (const auto& [k, v] : library_versions()) versions[k] = v;
  out["versions"] = versions;
  Json unknowns = Json::object();
  for (const UnknownBlock& b : layout.blocks()) unknowns[b.name] = b.size;
  unknowns["total"] = layout.size();
  out["unknowns"] = unknowns;
  // Wall times rounded to the microsecond: more digits are noise.
  const auto ms = [](double v) { return std::round(v * 1e3) / 1e3; };
  out["timings"] = {{"total_ms", ms(t.total_ms)},
                    {"setup_ms", ms(t.setup_ms)},
                    {"solve_ms", ms(t.solve_ms)},
                    {"states", t.states},
                    {"newton_iterations", t.newton_iterations},
                    {"jacobian_evaluations", t.jacobian_evaluations},
                    {"transients", t.transients},
                    {"ida_steps", t.ida_steps},
                    {"ida_factorizations", t.ida_factorizations},
                    {"klu_factorizations", t.klu_factorizations}};
  out["scene"] = scene_json(YAML::Load(resolved_scene_yaml));
  return out.dump(2) + "\n";
}

}  // namespace twb
