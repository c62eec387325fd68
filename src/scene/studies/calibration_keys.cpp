// study type calibration: inputs fitted to a rig's measurements.
#include <filesystem>

#include <fmt/format.h>

#include "scene/scene_names.h"
#include "scene/scene_sections.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type", "data", "fit", "sd", "max_iterations"};

// The data and the fitted inputs are read once every input is known (read_calibration).
void read(const MapReader& study, Scene& out) {
  CalibrationSettings& s = std::get<CalibrationSettings>(out.study.settings);
  study.get("data", "the path of the measurements file (CSV), e.g. rig.csv");
  s.fit_iterations = study.integer("max_iterations", 1, 1000, s.fit_iterations,
                                   "Levenberg-Marquardt iterations before the fit stops unconverged");
  study.get("fit", "a map from input paths to bounds, e.g. {surfaces.washer.Rq: {lower: 0.1 um, upper: 1.5 um}}");
}

void write(SceneText& w, const Study& study) {
  const CalibrationSettings& st = std::get<CalibrationSettings>(study.settings);
  w.entry(1, "data", quoted(std::filesystem::absolute(st.data).string()));
  w.line(1, "fit:");
  for (const FittedInput& f : st.fitted)
    w.entry(2, f.path, fmt::format("{{start: {}, lower: {}, upper: {}}}", quantity(f.start, f.unit),
                                    quantity(f.lower, f.unit), quantity(f.upper, f.unit)));
  const char* units[] = {"N m", "1", "K", "K"};
  std::string sd;
  for (std::size_t q = 0; q < kMeasuredQuantities; ++q)
    if (st.measurement_sd[q] > 0.0)
      sd += fmt::format("{}{}: {}", sd.empty() ? "" : ", ", kMeasuredNames[q], quantity(st.measurement_sd[q], units[q]));
  if (!sd.empty()) w.entry(1, "sd", fmt::format("{{{}}}", sd));
  w.entry(1, "max_iterations", fmt::format("{}", st.fit_iterations));
}

}  // namespace

extern const StudySection kCalibrationKeys{
    .keys = kKeys, .read = read, .read_after_inputs = read_calibration, .write = write};

}  // namespace twb::scene_io
