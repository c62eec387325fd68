// study type point: the bearing at the operating point, with its error bar.
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"
#include "scene/scene_names.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type", "error_estimate", "tolerance"};

// A point's bar is the two-mesh estimate unless a tolerance is asked for (PointSettings'
// default): to 1 % on every quantity a point would cost many times itself (h_min/σ near
// the contact converges slowest), and its bar's cost is a few times the point's.
void read(const MapReader& study, Scene& out) {
  ErrorBarSettings& bars = std::get<PointSettings>(out.study.settings).error_bars;
  bars.estimate = read_choice(study, "error_estimate", kErrorEstimates, bars.estimate);
  read_tolerance(study, bars);
  refuse_every_state(study, bars, "point");
}

void write(SceneText& w, const Study& st) {
  const ErrorBarSettings& bars = std::get<PointSettings>(st.settings).error_bars;
  // A point's bar is on unless it is turned off: the one choice it has is written, so
  // that the scene read back (run.json's) asks for what the run did.
  if (bars.estimate == ErrorEstimate::none) w.entry(1, "error_estimate", "none");
  write_tolerance(w, bars);
}

}  // namespace

extern const StudySection kPointKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
