#include "twb/results/limit_notes.h"

#include <map>
#include <optional>
#include <tuple>

#include <fmt/format.h>

#include "twb/results/run_axes.h"
#include "twb/scene/scene_loader.h"

namespace twb {

namespace {

// A run of a study: what tells its states apart besides the load.
using Run = std::tuple<double, std::vector<double>, std::optional<SlidingFilm>>;

struct FirstExcess {
  double load;
  LimitExcess excess;
  bool cool_branch;
};

}  // namespace

std::vector<std::string> limit_notes(const std::vector<SolvedState>& states, const std::vector<DistressRow>& distress,
                                     const std::vector<std::string>& parameter_columns, bool speeds_in_rpm) {
  std::map<Run, std::map<LimitKind, FirstExcess>> first;
  for (const SolvedState& r : states) {
    if (!r.converged) continue;
    auto& kinds = first[Run{r.state.speed, r.parameters, r.sliding}];
    for (const LimitExcess& e : r.state.limits) {
      auto [it, fresh] = kinds.try_emplace(e.kind, FirstExcess{r.state.load, e, r.branch == Branch::cool});
      if (!fresh && r.state.load < it->second.load) it->second = FirstExcess{r.state.load, e, r.branch == Branch::cool};
    }
  }
  std::vector<std::string> lines;
  for (const auto& [run, kinds] : first) {
    const auto& [speed, parameters, sliding] = run;
    std::optional<double> w_d;
    for (const DistressRow& d : distress)
      if (d.speed == speed && d.parameters == parameters && d.sliding == sliding) w_d = d.distress_load;
    const std::string where = fmt::format("{}{}{}", speed_text(speed, speeds_in_rpm), run_axes_text(parameter_columns, parameters),
                                          sliding ? ", sliding " + std::string(scene_name(*sliding)) : "");
    for (const auto& [kind, f] : kinds) {
      const bool before_distress = w_d && f.cool_branch && f.load < *w_d;
      lines.push_back(fmt::format("limit at {}: {} from {:.6g} N: {}{}", where, limit_name(kind), f.load,
                                  describe_limit(f.excess),
                                  before_distress
                                      ? fmt::format("; on the cool branch, below W_d = {:.2f} N: the bearing leaves "
                                                    "the model's range before distress",
                                                    *w_d)
                                      : ""));
    }
  }
  return lines;
}

}  // namespace twb
