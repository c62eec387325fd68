#include "twb/results/run_record.h"

#include <Eigen/Core>
#include <boost/version.hpp>
#include <fmt/format.h>
#include <klu.h>
#include <sundials/sundials_config.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <sstream>

namespace twb {

namespace {

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", int(c));
        else out += c;
    }
  }
  return out + "\"";
}

// A scalar that reads as a finite number is written as a JSON number.
std::string json_scalar(const std::string& s) {
  std::istringstream in(s);
  double v;
  if (in >> v && in.eof() && std::isfinite(v)) return s;
  if (s == "true" || s == "false") return s;
  return json_string(s);
}

std::string yaml_to_json(const YAML::Node& n, int indent) {
  const std::string pad(indent + 2, ' '), end_pad(indent, ' ');
  if (n.IsMap()) {
    std::string out = "{\n";
    bool first = true;
    for (const auto& kv : n) {
      out += (first ? "" : ",\n") + pad + json_string(kv.first.as<std::string>()) + ": " +
             yaml_to_json(kv.second, indent + 2);
      first = false;
    }
    return out + "\n" + end_pad + "}";
  }
  if (n.IsSequence()) {
    std::string out = "[";
    for (std::size_t i = 0; i < n.size(); ++i) out += (i ? ", " : "") + yaml_to_json(n[i], indent + 2);
    return out + "]";
  }
  if (n.IsScalar()) return json_scalar(n.Scalar());
  return "null";
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
      {"yaml-cpp", "0.7"},
      {"udunits2", "2"},
      {"compiler", __VERSION__},
  };
}

std::string run_json(const std::string& scene_path, const std::string& resolved_scene_yaml,
                     const UnknownLayout& layout, const RunTimings& t, const std::string& outcome) {
  std::string out = "{\n";
  out += "  \"scene_file\": " + json_string(scene_path) + ",\n";
  out += "  \"outcome\": " + json_string(outcome) + ",\n";
  out += "  \"versions\": {";
  bool first = true;
  for (const auto& [k, v] : library_versions()) {
    out += (first ? "\n" : ",\n") + std::string("    ") + json_string(k) + ": " + json_string(v);
    first = false;
  }
  out += "\n  },\n  \"unknowns\": {";
  first = true;
  for (const UnknownBlock& b : layout.blocks()) {
    out += (first ? "\n" : ",\n") + std::string("    ") + json_string(b.name) + ": " + std::to_string(b.size);
    first = false;
  }
  out += fmt::format(",\n    \"total\": {}\n  }},\n", layout.size());
  out += fmt::format(
      "  \"timings\": {{\"total_ms\": {:.3f}, \"setup_ms\": {:.3f}, \"solve_ms\": {:.3f}, \"states\": {}, "
      "\"newton_iterations\": {}, \"jacobian_evaluations\": {}, \"transients\": {}, \"ida_steps\": {}, "
      "\"klu_factorizations\": {}}},\n",
      t.total_ms, t.setup_ms, t.solve_ms, t.states, t.newton_iterations, t.jacobian_evaluations, t.transients,
      t.ida_steps, t.klu_factorizations);
  out += "  \"scene\": " + yaml_to_json(YAML::Load(resolved_scene_yaml), 2) + "\n}\n";
  return out;
}

}  // namespace twb
