// study type life: the washer worn at its operating point in the wear's slow time
// (docs/physics.md section 20).
#include <fmt/format.h>

#include "scene/physical_bounds.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type", "duration", "tolerance", "report_every", "failure_load"};

void read(const MapReader& study, Scene& out) {
  LifeSettings& s = std::get<LifeSettings>(out.study.settings);
  if (!out.effects.wear) {
    const Node type = study.get("type", "");
    type.fail(fmt::format("{}: a life study wears the washer (docs/physics.md section 20), so it needs the effect "
                          "'wear' and a wear_rate for both faces of the sliding film; add 'wear' to effects",
                          type.path()));
  }
  s.duration = study.quantity("duration", si::time, bounds::life_duration);
  s.tolerance = study.quantity("tolerance", si::length, bounds::depth_tolerance, s.tolerance);
  s.failure_load = study.boolean("failure_load", s.failure_load);
  if (!study.has("report_every")) return;
  const std::string reason = fmt::format("a time above 0 and at most the life's duration, {:g} s", s.duration);
  s.report_every = study.quantity("report_every", si::time,
                                  Range{.low = 0.0, .low_open = true, .high = s.duration, .reason = reason});
}

void write(SceneText& w, const Study& study) {
  const LifeSettings& s = std::get<LifeSettings>(study.settings);
  w.entry(1, "duration", quantity(s.duration, "s"), fmt::format("{:g} h", s.duration / 3600.0));
  w.entry(1, "tolerance", quantity(s.tolerance, "m"));
  if (s.report_every > 0.0) w.entry(1, "report_every", quantity(s.report_every, "s"));
  w.entry(1, "failure_load", s.failure_load ? "true" : "false");
}

}  // namespace

extern const StudySection kLifeKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
