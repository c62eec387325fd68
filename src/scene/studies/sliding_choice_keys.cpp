// study type sliding_choice: both films swept over a load grid, the one of lower friction
// torque chosen at each load.
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type", "load_start", "load_end", "load_steps", "speeds", "bracket_width"};

void read(const MapReader& study, Scene& out) {
  read_load_grid(study, out, std::get<SlidingChoiceSettings>(out.study.settings).grid);
}

void write(SceneText& w, const Study& study) { write_load_grid(w, std::get<SlidingChoiceSettings>(study.settings).grid); }

}  // namespace

extern const StudySection kSlidingChoiceKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
