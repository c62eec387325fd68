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

// A spread in the input's unit: for a temperature an interval, not a point of the scale
// ("3 degC" is 3 K, not 276.15 K): the value less the zero of the unit it is written in.
double spread(const MapReader& d, const char* key, const SiUnit& unit) {
  const Range range{.low = 0.0, .low_open = true, .reason = "the input's standard deviation"};
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
    u.sd = spread(d, "sd", unit);
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
  Study& s = out.study;
  if (s.type != StudyType::reliability) return;
  const MapReader study = scene.map("study", {std::begin(kStudyKeys), std::end(kStudyKeys)});
  const Node inputs = study.get("inputs", "");
  if (!inputs.yaml().IsMap() || inputs.yaml().size() == 0)
    inputs.fail(fmt::format("{}: {}; give a map from input paths to distributions, e.g. {{geometry.gear.tilt: "
                            "{{distribution: normal, mean: 0.5 mrad, sd: 0.1 mrad}}}}",
                            inputs.path(), inputs.yaml().IsMap() ? "no uncertain inputs" : inputs.describe_content()));
  std::vector<std::string> keys;
  for (const auto& kv : inputs.yaml()) keys.push_back(kv.first.as<std::string>());
  const MapReader map(inputs, std::vector<std::string_view>(keys.begin(), keys.end()));
  for (const std::string& path : map.keys()) {
    const Node entry = map.get(path, "");
    if (path == "operating.load")
      entry.fail(fmt::format("{}: the operating load is the load whose probability of failure is taken, not an uncertain "
                             "input",
                             entry.path()));
    SceneInput input;
    try {
      input = scene_input(out, path);
    } catch (const std::invalid_argument& e) {
      entry.fail(fmt::format("{}: {}", entry.path(), e.what()));
    }
    s.uncertain_inputs.push_back(read_distribution(entry, input, out));
  }
}

}  // namespace twb::scene_io
