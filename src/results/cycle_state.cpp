#include "twb/results/cycle_state.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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
  std::istringstream in(resolved_scene);
  std::string out, line;
  bool skipping = false;
  for (; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (line[0] != ' ') {
      const std::string key = line.substr(0, line.find(':'));
      skipping = key == "study" || key == "output" || key == "operating";
    }
    if (!skipping) out += line + "\n";
  }
  return out;
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
  Json j;
  try {
    j = Json::parse(in);
  } catch (const Json::exception& e) {
    throw std::invalid_argument(fmt::format("{}: not a cycle's end state (JSON: {})", path, e.what()));
  }
  try {
    if (j.at("format") != "twb-cycle-state 1")
      throw std::invalid_argument(fmt::format("{}: format '{}', this twb reads 'twb-cycle-state 1'", path,
                                              j.at("format").dump()));
    CycleState s;
    s.time = j.at("time_s").get<double>();
    s.load = j.at("load_N").get<double>();
    s.speed = j.at("speed_rad_s").get<double>();
    s.ambient = j.at("ambient_K").get<double>();
    s.tilt = j.at("tilt_rad").get<double>();
    s.unknowns = j.at("unknowns").get<std::vector<double>>();
    s.bearing = j.at("bearing").get<std::string>();
    return s;
  } catch (const Json::exception& e) {
    throw std::invalid_argument(fmt::format("{}: not a cycle's end state ({})", path, e.what()));
  }
}

}  // namespace twb
