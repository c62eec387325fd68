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
  check_marched_in_real_time(study, out, "a duty cycle");
}

void write(SceneText& w, const Study& study) {
  const DutyCycleSettings& st = std::get<DutyCycleSettings>(study.settings);
  write_schedule(w, st);
  w.entry(1, "failure_load_at_worst", st.failure_load_at_worst ? "true" : "false");
  w.entry(1, "relative_tolerance", quantity(st.march_tolerance, "1"));
}

}  // namespace

extern const StudySection kDutyCycleKeys{
    .keys = kKeys, .read = read, .read_after_inputs = read_schedule, .write = write};

}  // namespace twb::scene_io
