// study type transient: a load step marched in pseudo-time.
#include <fmt/format.h>

#include "scene/physical_bounds.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type", "load_start", "load_end", "duration"};

void read(const MapReader& study, Scene& out) {
  LoadStepSettings& s = std::get<LoadStepSettings>(out.study.settings);
  if (!out.effects.thermal) {
    const Node type = study.get("type", "");
    type.fail(fmt::format("{}: a transient study marches the heat balance in pseudo-time (docs/physics.md "
                          "section 8), so it needs the thermal effect; add 'thermal' to effects",
                          type.path()));
  }
  s.loads.start = study.quantity("load_start", si::force, bounds::load);
  s.loads.end = study.quantity("load_end", si::force, bounds::load);
  s.duration = study.quantity("duration", si::time, bounds::duration, 0.0);
}

void write(SceneText& w, const Study& study) {
  const LoadStepSettings& s = std::get<LoadStepSettings>(study.settings);
  write_load_range(w, s.loads);
  w.entry(1, "duration", quantity(s.duration, "s"));
}

}  // namespace

extern const StudySection kTransientKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
