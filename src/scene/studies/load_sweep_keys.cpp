// study type load_sweep: a load grid at each speed (and map combination), past distress.
#include "scene/scene_names.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type",          "load_start",     "load_end",  "load_steps", "speeds",
                                      "parameter",     "bracket_width",  "error_estimate", "tolerance"};

void read(const MapReader& study, Scene& out) {
  LoadSweepSettings& s = std::get<LoadSweepSettings>(out.study.settings);
  read_load_grid(study, out, s.grid);
  s.error_bars.estimate = read_choice(study, "error_estimate", kErrorEstimates, s.error_bars.estimate);
  read_tolerance(study, s.error_bars);
  read_map_axes(study, s.axes, out);
}

void write(SceneText& w, const Study& study) {
  const LoadSweepSettings& s = std::get<LoadSweepSettings>(study.settings);
  write_load_grid(w, s.grid, s.axes);
  write_error_estimate(w, s.error_bars);
  write_tolerance(w, s.error_bars);
}

}  // namespace

extern const StudySection kLoadSweepKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
