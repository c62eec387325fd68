// A calibration study (docs/scenes.md, study type calibration):
//   data: rig.csv                          # the measurements (scene/measurements.h)
//   fit:
//     surfaces.washer.Rq: {start: 0.4 um, lower: 0.1 um, upper: 1.5 um}
//     friction.boundary_coefficient: {lower: 0.02, upper: 0.3}    # start: the scene's value
//   sd: {torque: 0.01 N m, T_mean: 2 K}   # each measured quantity's standard deviation
// Each fitted value in the input's own kind of unit, its bounds ones the scene accepts.
// A standard deviation for every quantity the data measure (each reading's own, from a
// `<quantity>_sd` column of the data, or one for all its readings in `sd`), or for none
// (a relative fit).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scene/measurements.h"
#include "scene_names.h"
#include "scene_sections.h"
#include "twb/scene/scene_inputs.h"

namespace twb::scene_io {

namespace {

FittedInput read_fitted(const Node& entry, const SceneInput& input, const Scene& out) {
  FittedInput f;
  f.path = input.path;
  f.unit = input.unit;
  const MapReader d(entry, {"start", "lower", "upper"});
  const SiUnit& unit = si::of_symbol(input.unit);
  d.get("lower", "the least value the fit may take, in the input's unit");
  d.get("upper", "the largest value the fit may take, in the input's unit");
  f.lower = d.quantity("lower", unit, Range{});
  f.upper = d.quantity("upper", unit, Range{});
  if (!(f.upper > f.lower)) {
    const Node upper = d.get("upper", "");
    upper.fail(fmt::format("{}: '{}' must be greater than lower '{}'", upper.path(), upper.yaml().Scalar(),
                           d.get("lower", "").yaml().Scalar()));
  }
  f.start = d.quantity("start", unit, Range{}, input.value);
  if (!(f.start >= f.lower && f.start <= f.upper)) {
    const Node at = d.has("start") ? d.get("start", "") : entry;
    at.fail(fmt::format("{}: the fit's start {:.6g} {}{} lies outside its bounds [{:.6g}, {:.6g}] {}", at.path(), f.start,
                        input.unit, d.has("start") ? "" : " (the scene's value)", f.lower, f.upper, input.unit));
  }
  // Every value between the bounds is one the fit may try: the scene must take both ends.
  for (const double value : {f.lower, f.upper})
    if (const std::optional<InputError> e = refused(out, input, value))
      entry.fail(fmt::format("{}: the fit may reach {:.6g} {}, which the scene refuses: {}; narrow the bounds",
                             entry.path(), value, input.unit, e->message()));
  return f;
}

}  // namespace

void read_calibration(const MapReader& scene, Scene& out) {
  CalibrationSettings& s = std::get<CalibrationSettings>(out.study.settings);
  const MapReader study = scene.map("study", {std::begin(kStudyKeys), std::end(kStudyKeys)});
  const Node data = study.get("data", "the path of the measurements file (CSV), e.g. rig.csv");
  s.data = named_file_path(data, "the path of the measurements file (CSV), e.g. rig.csv");
  // A file that is not there is a fault of the scene, at its key; what is wrong inside
  // one is located in it (scene/measurements.h).
  std::error_code error;
  if (!std::filesystem::is_regular_file(s.data, error))
    data.fail(fmt::format("{}: cannot read the measurements '{}': no such regular file (a path relative to the scene "
                          "file's directory)",
                          data.path(), s.data));
  s.measurements = read_measurements(s.data);

  const std::vector<InputEntry> entries = input_entries(
      study.get("fit", ""), out, "no fitted inputs",
      "bounds, e.g. {surfaces.washer.Rq: {start: 0.4 um, lower: 0.1 um, upper: 1.5 um}}", [&](const std::string& path) {
        const bool own_ambient = std::any_of(s.measurements.begin(), s.measurements.end(),
                                             [](const MeasuredPoint& p) { return p.ambient > 0.0; });
        if (path == "operating.ambient" && own_ambient)
          return std::string("the data give measured points their own ambient temperature; it is not fitted");
        return path == "operating.load" || path == "operating.speed"
                   ? fmt::format("each measured point has its own {}; it is not fitted",
                                 path == "operating.load" ? "load" : "speed")
                   : std::string();
      });
  for (const auto& [entry, input] : entries) {
    s.fitted.push_back(read_fitted(entry, input, out));
  }

  // Which quantities the data measure, and which with each reading's own deviation; a
  // deviation for every measured quantity (from the data or `sd`, not both) or for none.
  std::array<bool, kMeasuredQuantities> measured{}, own_sd{};
  for (const MeasuredPoint& p : s.measurements)
    for (std::size_t q = 0; q < kMeasuredQuantities; ++q) {
      measured[q] = measured[q] || !std::isnan(p.values[q]);
      own_sd[q] = own_sd[q] || !std::isnan(p.sd[q]);
    }
  if (!study.has("sd")) {
    const bool any = std::any_of(own_sd.begin(), own_sd.end(), [](bool b) { return b; });
    for (std::size_t q = 0; q < kMeasuredQuantities; ++q)
      if (any && measured[q] && !own_sd[q])
        data.fail(fmt::format("{}: the data give their readings' standard deviations for some quantities but not "
                              "for {}: give a {}_sd column, or study.sd: {{{}: ...}}, so that every reading is "
                              "weighed by its deviation (or give none, for a relative fit)",
                              data.path(), kMeasuredNames[q], kMeasuredNames[q], kMeasuredNames[q]));
    return;
  }
  const MapReader sd = study.map("sd", {std::begin(kMeasuredNames), std::end(kMeasuredNames)});
  const SiUnit* units[] = {&si::torque, &si::dimensionless, &si::temperature, &si::temperature};
  for (std::size_t q = 0; q < kMeasuredQuantities; ++q) {
    const std::string key(kMeasuredNames[q]);
    if (sd.has(key)) {
      if (!measured[q] || own_sd[q]) {
        const Node node = sd.get(key, "");
        node.fail(own_sd[q] ? fmt::format("{}: the data give each {} reading its own standard deviation ({}_sd); "
                                          "leave it out",
                                          node.path(), key, key)
                            : fmt::format("{}: the data measure no {}; leave it out", node.path(), key));
      }
      s.measurement_sd[q] = read_spread(sd, key.c_str(), *units[q], "the measurement's standard deviation");
    } else if (measured[q] && !own_sd[q]) {
      sd.node().fail(fmt::format("{}: no standard deviation for {}, which the data measure; give one for every "
                                 "measured quantity (here or as a {}_sd column of the data), or leave sd out to fit "
                                 "relative residuals",
                                 sd.node().path(), key, key));
    }
  }
}

}  // namespace twb::scene_io
