#include "twb/results/cycle_state.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

namespace twb {

namespace {

using Json = nlohmann::ordered_json;

// A number as JSON can hold it bit for bit: finite doubles only (an unknown is never
// anything else in a state IDA reached).
double finite(double v, const char* what) {
  if (!std::isfinite(v)) throw std::invalid_argument(fmt::format("{} is not a finite number", what));
  return v;
}

}  // namespace

std::string bearing_of(const std::string& resolved_scene) {
  YAML::Node scene = YAML::Load(resolved_scene);
  scene.remove("study");
  scene.remove("output");
  // The schedule's inputs; the rest of operating (which film slides) is the bearing's.
  if (YAML::Node operating = scene["operating"])
    for (const char* key : {"load", "speed", "ambient"}) operating.remove(key);
  if (YAML::Node gear = scene["geometry"]["gear"]) gear.remove("tilt");
  YAML::Emitter out;
  out << scene;
  return std::string(out.c_str()) + "\n";
}

std::string cycle_state_json(const CycleState& s) {
  Json j;
  j["format"] = "twb-cycle-state 1";
  j["time_s"] = finite(s.time, "the time");
  j["load_N"] = finite(s.load, "the load");
  j["speed_rad_s"] = finite(s.speed, "the speed");
  j["ambient_K"] = finite(s.ambient, "the ambient");
  j["tilt_rad"] = finite(s.tilt, "the tilt");
  for (double u : s.unknowns) finite(u, "an unknown");
  j["unknowns"] = s.unknowns;
  j["bearing"] = s.bearing;
  // 17 significant digits (nlohmann's shortest round trip): every double read back exactly.
  return j.dump(1) + "\n";
}

CycleState read_cycle_state(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(fmt::format("{}: cannot read it (a results directory of a duty cycle holds one)", path));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return cycle_state_of(text, path);
}

CycleState cycle_state_of(const std::string& json, const std::string& path) {
  Json j;
  try {
    j = Json::parse(json);
  } catch (const Json::exception& e) {
    throw std::invalid_argument(fmt::format("{}: not a cycle's end state (JSON: {})", path, e.what()));
  }
  try {
    if (j.at("format") != "twb-cycle-state 1")
      throw std::invalid_argument(fmt::format("format {}, this twb reads 'twb-cycle-state 1'", j.at("format").dump()));
    CycleState s;
    s.time = j.at("time_s").get<double>();
    s.load = j.at("load_N").get<double>();
    s.speed = j.at("speed_rad_s").get<double>();
    s.ambient = j.at("ambient_K").get<double>();
    s.tilt = j.at("tilt_rad").get<double>();
    s.unknowns = j.at("unknowns").get<std::vector<double>>();
    s.bearing = j.at("bearing").get<std::string>();
    // As written: finite numbers only (a hand-edited file must not reach the solver).
    for (double v : {s.time, s.load, s.speed, s.ambient, s.tilt}) finite(v, "a time or an input");
    for (double u : s.unknowns) finite(u, "an unknown");
    return s;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: not a cycle's end state ({})", path, e.what()));
  } catch (const Json::exception& e) {
    throw std::invalid_argument(fmt::format("{}: not a cycle's end state ({})", path, e.what()));
  }
}

}  // namespace twb
