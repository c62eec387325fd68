// A reliability study's uncertain inputs (docs/scenes.md, study type reliability):
//   inputs:
//     geometry.gear.tilt: {distribution: truncated_normal, mean: 0.5 mrad, sd: 0.2 mrad, lower: 0 rad, upper: 2 mrad}
//     surfaces.washer.Rq: {distribution: lognormal, sd: 0.05 um}     # mean: the scene's value
// Each value in the input's own kind of unit; every value the distribution reaches within
// four standard deviations (or its bounds) must be one the scene accepts, so that no
// sample of the analysis falls outside the model.
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scene_names.h"
#include "scene_sections.h"
#include "scene/input_distribution.h"
#include "twb/scene/scene_inputs.h"

namespace twb::scene_io {

namespace {

constexpr double kReach = 4.0;  // standard deviations a normal's values are checked to

}  // namespace

double read_spread(const MapReader& d, const char* key, const SiUnit& unit, std::string_view reason) {
  const Range range{.low = 0.0, .low_open = true, .reason = reason};
  if (unit.symbol != si::temperature.symbol) return d.quantity(key, unit, range);
  const Node node = d.get(key, "a temperature interval, e.g. 3 K");
  const double value = node.quantity(unit, Range{});
  const std::string text = node.yaml().Scalar();
  const std::size_t space = text.find_first_of(" \t");
  const double zero = space == std::string::npos ? 0.0 : to_si(fmt::format("0{}", text.substr(space)), unit);
  if (!range.contains(value - zero))
    node.fail(fmt::format("{}: '{}' must be {} ({})", node.path(), text, range.describe(), range.reason));
  return value - zero;
}

namespace {

UncertainInput read_distribution(const Node& entry, const SceneInput& input, const Scene& out) {
  UncertainInput u;
  u.path = input.path;
  u.unit = input.unit;
  const MapReader d(entry, {"distribution", "mean", "sd", "lower", "upper"});
  d.get("distribution", "normal, lognormal, uniform or truncated_normal");
  u.distribution = read_choice(d, "distribution", kInputDistributions, u.distribution);
  const SiUnit unit = si::of_symbol(input.unit);
  switch (u.distribution) {
    case InputDistribution::normal:
      d.restrict_to({"distribution", "mean", "sd"}, "with distribution: normal");
      break;
    case InputDistribution::lognormal:
      d.restrict_to({"distribution", "mean", "sd"}, "with distribution: lognormal");
      break;
    case InputDistribution::uniform:
      d.restrict_to({"distribution", "lower", "upper"}, "with distribution: uniform");
      break;
    case InputDistribution::truncated_normal:
      break;
  }
  const bool bounded = has_bounds(u.distribution);
  if (has_mean_and_sd(u.distribution)) {
    const Range mean_range = u.distribution == InputDistribution::lognormal
                                 ? Range{.low = 0.0, .low_open = true, .reason = "a lognormal input's mean"}
                                 : Range{};
    u.mean = d.quantity("mean", unit, mean_range, input.value);
    if (!mean_range.contains(u.mean))
      entry.fail(fmt::format("{}: the scene's value {:.6g} {} cannot be a lognormal input's mean (it must be > 0); "
                             "give a mean",
                             entry.path(), input.value, input.unit));
    u.sd = read_spread(d, "sd", unit, "the input's standard deviation");
  }
  if (bounded) {
    u.lower = d.quantity("lower", unit, Range{});
    u.upper = d.quantity("upper", unit, Range{});
    if (!(u.upper > u.lower)) {
      const Node upper = d.get("upper", "");
      upper.fail(fmt::format("{}: '{}' must be greater than lower '{}'", upper.path(), upper.yaml().Scalar(),
                             d.get("lower", "").yaml().Scalar()));
    }
  }
  // The values the analysis may reach, each tried on the scene once.
  std::vector<double> reached;
  if (u.distribution == InputDistribution::normal || u.distribution == InputDistribution::lognormal) {
    reached = {input_at(u, -kReach), input_at(u, kReach)};
  } else {
    reached = {u.lower, u.upper};
  }
  for (const double value : reached)
    if (const std::optional<InputError> e = refused(out, input, value))
      entry.fail(fmt::format("{}: {} reaches {:.6g} {}{}, which the scene refuses: {}{}", entry.path(), describe(u), value,
                             input.unit, bounded ? "" : fmt::format(" within {} standard deviations", kReach),
                             e->message(),
                             bounded ? ""
                             : u.distribution == InputDistribution::normal
                                 ? "; bound it (truncated_normal with lower and upper) or take a lognormal"
                                 : "; bound it (truncated_normal with lower and upper) or narrow it"));
  return u;
}

}  // namespace

void read_uncertain_inputs(const MapReader& scene, Scene& out) {
  ReliabilitySettings& s = std::get<ReliabilitySettings>(out.study.settings);
  const MapReader study = scene.map("study", {std::begin(kStudyKeys), std::end(kStudyKeys)});
  const std::vector<InputEntry> entries = input_entries(
      study.get("inputs", ""), out, "no uncertain inputs",
      "distributions, e.g. {geometry.gear.tilt: {distribution: normal, mean: 0.5 mrad, sd: 0.1 mrad}}",
      [](const std::string& path) {
        return path == "operating.load"
                   ? std::string("the operating load is the load whose probability of failure is taken, not an "
                                 "uncertain input")
                   : std::string();
      });
  for (const auto& [entry, input] : entries) {
    s.uncertain_inputs.push_back(read_distribution(entry, input, out));
  }
}

}  // namespace twb::scene_io
