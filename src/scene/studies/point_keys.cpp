// study type point: the bearing at the operating point, with its error bar.
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"
#include "scene/scene_names.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type", "error_estimate", "tolerance"};

void read(const MapReader& study, Scene& out) {
  Study& s = out.study;
  s.error_estimate = read_choice(study, "error_estimate", kErrorEstimates, s.error_estimate);
  // A point's bar is the two-mesh estimate unless a tolerance is asked for: to 1 % on
  // every quantity a point would cost many times itself (h_min/σ near the contact
  // converges slowest), and its bar's cost is a few times the point's.
  s.tolerance = 0.0;
  read_tolerance(study, s);
  refuse_every_state(study, s, "point");
}

void write(SceneText& w, const Study& st) {
  // A point's bar is on unless it is turned off: the one choice it has is written, so
  // that the scene read back (run.json's) asks for what the run did.
  if (st.error_estimate == ErrorEstimate::none) w.entry(1, "error_estimate", "none");
  write_tolerance(w, st);
}

}  // namespace

extern const StudySection kPointKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
