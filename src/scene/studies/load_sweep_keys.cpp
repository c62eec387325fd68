// study type load_sweep: a load grid at each speed (and map combination), past distress.
#include "scene/scene_names.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type",          "load_start",     "load_end",  "load_steps", "speeds",
                                      "parameter",     "bracket_width",  "error_estimate", "tolerance"};

void read(const MapReader& study, Scene& out) {
  Study& s = out.study;
  read_load_grid(study, out);
  s.error_estimate = read_choice(study, "error_estimate", kErrorEstimates, s.error_estimate);
  read_tolerance(study, s);
  read_map_axes(study, s, out);
}

void write(SceneText& w, const Study& st) {
  write_load_grid(w, st);
  write_error_estimate(w, st);
  write_tolerance(w, st);
}

}  // namespace

extern const StudySection kLoadSweepKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
