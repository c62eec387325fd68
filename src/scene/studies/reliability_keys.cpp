// study type reliability: the probability of failure over uncertain inputs.
#include <fmt/format.h>

#include "scene/input_distribution.h"
#include "scene/scene_names.h"
#include "scene/scene_sections.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type",          "inputs",        "load_start", "load_end",
                                      "bracket_width", "probabilities", "monte_carlo"};

// The inputs' distributions are read once every input is known (read_uncertain_inputs).
void read(const MapReader& study, Scene& out) {
  ReliabilitySettings& s = std::get<ReliabilitySettings>(out.study.settings);
  read_load_range(study, s.search.loads, " (the failure search at the inputs' medians runs between them)");
  // A sample that does not fail up to load_end must be known to survive the operating load.
  if (!(out.operating.load > s.search.loads.start && out.operating.load < s.search.loads.end)) {
    const Node end = study.get("load_end", "");
    end.fail(fmt::format("{}: the operating load {:.6g} N must lie between load_start and load_end: the "
                         "probability of failure at it needs each failure search to reach past it",
                         end.path(), out.operating.load));
  }
  s.search.bracket_width = read_bracket_width(study, s.search.bracket_width);
  study.get("inputs", "a map from input paths to distributions, e.g. {geometry.gear.tilt: {distribution: normal, "
                      "mean: 0.5 mrad, sd: 0.1 mrad}}");
  if (study.has("probabilities")) {
    const Node list = study.get("probabilities", "");
    for (const Node& item : list.list("failure probabilities, e.g. [1e-4, 1e-3, 1e-2]"))
      s.probabilities.push_back(item.quantity(
          si::dimensionless, Range{.low = 0.0, .low_open = true, .high = 1.0, .high_open = true,
                                   .reason = "a probability of failure whose load is wanted, e.g. 1e-3"}));
  }
  const MapReader sampling = study.map("monte_carlo", {"cov", "max_samples", "seed"});
  s.sampling_cov = sampling.quantity(
      "cov", si::dimensionless,
      Range{.low = 0.0, .low_open = true, .high = 1.0, .reason = "the estimate's coefficient of variation, e.g. 0.1"},
      s.sampling_cov);
  s.max_samples = sampling.integer("max_samples", 0, 1000000, s.max_samples, "samples at most; 0: no Monte Carlo check");
  s.seed = sampling.integer("seed", 0, int(s.seed), "the samples' seed");
}

void write(SceneText& w, const Study& study) {
  const ReliabilitySettings& st = std::get<ReliabilitySettings>(study.settings);
  write_load_range(w, st.search.loads);
  w.entry(1, "bracket_width", quantity(st.search.bracket_width, "1"));
  w.line(1, "inputs:");
  for (const UncertainInput& in : st.uncertain_inputs) {
    std::string d = fmt::format("{{distribution: {}", kInputDistributions.name(in.distribution));
    if (has_mean_and_sd(in.distribution))
      d += fmt::format(", mean: {}, sd: {}", quantity(in.mean, in.unit), quantity(in.sd, in.unit));
    if (has_bounds(in.distribution))
      d += fmt::format(", lower: {}, upper: {}", quantity(in.lower, in.unit), quantity(in.upper, in.unit));
    w.entry(2, in.path, d + "}");
  }
  std::string probabilities;
  for (double p : st.probabilities) probabilities += (probabilities.empty() ? "" : ", ") + quantity(p, "1");
  if (!probabilities.empty()) w.entry(1, "probabilities", fmt::format("[{}]", probabilities));
  w.line(1, "monte_carlo:");
  w.entry(2, "cov", quantity(st.sampling_cov, "1"));
  w.entry(2, "max_samples", fmt::format("{}", st.max_samples));
  w.entry(2, "seed", fmt::format("{}", st.seed));
}

}  // namespace

extern const StudySection kReliabilityKeys{
    .keys = kKeys, .read = read, .read_after_inputs = read_uncertain_inputs, .write = write};

}  // namespace twb::scene_io
