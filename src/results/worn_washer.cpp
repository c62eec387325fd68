#include "twb/results/worn_washer.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "twb/error_family.h"

namespace twb {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kFormat = "twb-worn-washer 1";

void check_depths(const std::vector<double>& depths, std::size_t count, const char* face) {
  if (depths.size() != count)
    throw std::invalid_argument(fmt::format("{} depths: {} of them, the grid has {}", face, depths.size(), count));
  for (double d : depths)
    if (!std::isfinite(d)) throw std::invalid_argument(fmt::format("a {} depth is not a finite number", face));
}

// What every worn washer must be, read or about to be written.
void check(const WornWasher& w) {
  if (!std::isfinite(w.time) || w.time < 0.0) throw std::invalid_argument("the time is not a time of a life");
  if (w.film != 1 && w.film != 2) throw std::invalid_argument(fmt::format("film {}: 1 or 2", w.film));
  if (!(w.inner_radius > 0.0) || !(w.outer_radius > w.inner_radius) || !std::isfinite(w.outer_radius))
    throw std::invalid_argument("the radii are not an annulus");
  if (w.radial_nodes < 2 || w.circumferential_nodes < 3) throw std::invalid_argument("the grid has too few nodes");
  check_depths(w.rest, std::size_t(w.radial_nodes) * std::size_t(w.circumferential_nodes), "face at rest");
  check_depths(w.turn, std::size_t(w.radial_nodes), "turning face");
}

// The field `name` of j as a T, or why not, naming it.
template <class T>
T field(const Json& j, const char* name, const char* what) {
  if (!j.contains(name)) throw std::invalid_argument(fmt::format("no field '{}'", name));
  try {
    return j.at(name).get<T>();
  } catch (const Json::exception&) {
    throw std::invalid_argument(fmt::format("'{}' is not {}", name, what));
  }
}

}  // namespace

std::string worn_washer_json(const WornWasher& w) {
  check(w);
  Json j;
  j["format"] = kFormat;
  j["time_s"] = w.time;
  j["film"] = w.film;
  j["inner_radius_m"] = w.inner_radius;
  j["outer_radius_m"] = w.outer_radius;
  j["radial_nodes"] = w.radial_nodes;
  j["circumferential_nodes"] = w.circumferential_nodes;
  j["rest_m"] = w.rest;
  j["turn_m"] = w.turn;
  // 17 significant digits (nlohmann's shortest round trip): every depth read back exactly.
  return j.dump(1) + "\n";
}

WornWasher read_worn_washer(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(fmt::format("{}: cannot read it (a life study's results directory holds one)", path));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return worn_washer_of(text, path);
}

WornWasher worn_washer_of(const std::string& json, const std::string& where) {
  auto refuse = [&](const std::string& why) {
    return std::invalid_argument(fmt::format("{}: not a worn washer ({})", where, why));
  };
  Json j;
  try {
    j = Json::parse(json);
  } catch (const Json::exception& e) {
    throw refuse(fmt::format("JSON: {}", e.what()));
  }
  try {
    if (!j.is_object() || !j.contains("format") || j.at("format") != kFormat)
      throw std::invalid_argument(fmt::format("format {}, this twb reads '{}'",
                                              j.is_object() && j.contains("format") ? j.at("format").dump() : "none",
                                              kFormat));
    WornWasher w;
    w.time = field<double>(j, "time_s", "a number of seconds");
    w.film = field<int>(j, "film", "a film's number");
    w.inner_radius = field<double>(j, "inner_radius_m", "a radius in metres");
    w.outer_radius = field<double>(j, "outer_radius_m", "a radius in metres");
    w.radial_nodes = field<int>(j, "radial_nodes", "a count of nodes");
    w.circumferential_nodes = field<int>(j, "circumferential_nodes", "a count of nodes");
    w.rest = field<std::vector<double>>(j, "rest_m", "a list of depths in metres");
    w.turn = field<std::vector<double>>(j, "turn_m", "a list of depths in metres");
    w.source = where;
    check(w);
    return w;
  } catch (const std::invalid_argument& e) {
    throw refuse(e.what());
  } catch (const Json::exception& e) {
    throw refuse(e.what());
  }
}

ResultTable worn_profile_table(const std::vector<WornWasher>& along_life) {
  constexpr double um = 1e6, hour = 3600.0;
  ResultTable t;
  const auto time = t.number("t_h"), r = t.number("r_m"), theta = t.number("theta_rad");
  const auto rest = t.number("worn_rest_um"), turn = t.number("worn_turn_um");
  const auto rest_rq = t.number("rq_rest_um"), turn_rq = t.number("rq_turn_um");
  for (const WornWasher& w : along_life) {
    const int nr = w.radial_nodes, nt = w.circumferential_nodes;
    if (w.rest_rq.size() != w.rest.size() || w.turn_rq.size() != w.turn.size())
      throw InternalError("worn_profile_table: a worn washer without its faces' Rq");
    const double dr = (w.outer_radius - w.inner_radius) / (nr - 1);
    for (int i = 0; i < nr; ++i)
      for (int j = 0; j < nt; ++j) {
        t.put_number(time, w.time / hour);
        t.put_number(r, w.inner_radius + i * dr);
        t.put_number(theta, 2.0 * std::numbers::pi * j / nt);
        t.put_number(rest, um * w.rest[std::size_t(i * nt + j)]);
        t.put_number(turn, um * w.turn[std::size_t(i)]);
        t.put_number(rest_rq, um * w.rest_rq[std::size_t(i * nt + j)]);
        t.put_number(turn_rq, um * w.turn_rq[std::size_t(i)]);
      }
  }
  return t;
}

}  // namespace twb
