// study type duty_cycle: the bearing marched in real time through a schedule.
#include <fmt/format.h>

#include "scene/physical_bounds.h"
#include "scene/scene_sections.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type", "schedule", "failure_load_at_worst", "relative_tolerance"};

// The schedule is read once the operating point is known (read_schedule).
void read(const MapReader& study, Scene& out) {
  DutyCycleSettings& s = std::get<DutyCycleSettings>(out.study.settings);
  s.failure_load_at_worst = study.boolean("failure_load_at_worst", s.failure_load_at_worst);
  s.march_tolerance = study.quantity("relative_tolerance", si::dimensionless, bounds::march_tolerance, s.march_tolerance);
  if (!out.effects.thermal) {
    const Node type = study.get("type", "");
    type.fail(fmt::format("{}: a duty cycle marches the bodies' heat in time (docs/physics.md section 19), so it "
                          "needs the thermal effect; add 'thermal' to effects",
                          type.path()));
  }
  if (out.effects.hydrodynamics && out.effects.cavitation == CavitationModel::jfo) {
    const Node type = study.get("type", "");
    type.fail(fmt::format("{}: a duty cycle solves the film's squeeze (docs/physics.md section 19) with the "
                          "Reynolds cavitation condition only: the mass-conserving model's film content would "
                          "be a differential unknown held at 1 wherever the film is full (a DAE of index two, "
                          "not solved); use hydrodynamics: {{cavitation: reynolds}}",
                          type.path()));
  }
}

void write(SceneText& w, const Study& study) {
  const DutyCycleSettings& st = std::get<DutyCycleSettings>(study.settings);
  // Every point with every field: the resolved scene needs no schedule file.
  w.line(1, "schedule:");
  for (const SchedulePoint& p : st.schedule)
    w.line(2, fmt::format("- {{t: {}, load: {}, speed: {}, ambient: {}, tilt: {}}}", quantity(p.time, "s"),
                          quantity(p.load, "N"), quantity(p.speed, "rad/s"), quantity(p.ambient, "K"),
                          quantity(p.tilt, "rad")));
  w.entry(1, "failure_load_at_worst", st.failure_load_at_worst ? "true" : "false");
  w.entry(1, "relative_tolerance", quantity(st.march_tolerance, "1"));
}

}  // namespace

extern const StudySection kDutyCycleKeys{
    .keys = kKeys, .read = read, .read_after_inputs = read_schedule, .write = write};

}  // namespace twb::scene_io
