// study type life: the washer worn at its operating point, or through a duty cycle
// repeated, in the wear's slow time (docs/physics.md section 20).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "scene/physical_bounds.h"
#include "scene/scene_sections.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

// A life's cycle march's relative tolerance by default: a cycle's wear errs relatively by
// about five times it (measured on the paper's washer: 5e-5 at 1e-5, 3e-3 at 1e-4), so
// that at 1e-5 a depth of the 20 µm a washer may be allowed keeps its error below a
// nanometre.
constexpr double kCycleMarchTolerance = 1e-5;

constexpr std::string_view kKeys[] = {"type",         "duration",     "tolerance",         "report_every",
                                      "failure_load", "schedule", "relative_tolerance"};

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
  if (study.has("schedule")) {
    check_marched_in_real_time(study, out, "a life through a duty cycle");
    s.cycle.emplace();
    s.cycle->march_tolerance =
        study.quantity("relative_tolerance", si::dimensionless, bounds::march_tolerance, kCycleMarchTolerance);
  } else if (study.has("relative_tolerance")) {
    const Node key = study.get("relative_tolerance", "");
    key.fail(fmt::format("{}: the relative tolerance of a duty cycle's march, for a life through a repeated "
                         "schedule: give the life a schedule, or leave it out (at one operating point the depths' "
                         "error is study.tolerance)",
                         key.path()));
  }
  if (!study.has("report_every")) return;
  const std::string reason = fmt::format("a time above 0 and at most the life's duration, {:g} s", s.duration);
  s.report_every = study.quantity("report_every", si::time,
                                  Range{.low = 0.0, .low_open = true, .high = s.duration, .reason = reason});
}

// A repeated schedule is read once the operating point is known. Its end must be its
// start (load, speed, ambient and tilt), so that the cycles join without a jump of the
// inputs, and one cycle must fit in the life.
void read_cycle(const MapReader& scene, Scene& out) {
  LifeSettings& s = std::get<LifeSettings>(out.study.settings);
  if (!s.cycle) return;
  const Node schedule = read_schedule_into(scene, out, *s.cycle);
  const SchedulePoint &first = s.cycle->schedule.front(), &last = s.cycle->schedule.back();
  const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); };
  if (!same(first.load, last.load) || !same(first.speed, last.speed) || !same(first.ambient, last.ambient) ||
      !same(first.tilt, last.tilt))
    schedule.fail(fmt::format(
        "{}: a life repeats its schedule, so the cycle must end where it starts: the last point has {:.6g} N, "
        "{:.6g} rad/s, ambient {:.6g} K, tilt {:.6g} rad where the first has {:.6g} N, {:.6g} rad/s, {:.6g} K, "
        "{:.6g} rad; add a point that returns to the start",
        schedule.path(), last.load, last.speed, last.ambient, last.tilt, first.load, first.speed, first.ambient,
        first.tilt));
  const double period = last.time - first.time;
  if (period > s.duration)
    schedule.fail(fmt::format("{}: the cycle lasts {:.6g} s, longer than the life's duration {:.6g} s",
                              schedule.path(), period, s.duration));
}

void write(SceneText& w, const Study& study) {
  const LifeSettings& s = std::get<LifeSettings>(study.settings);
  w.entry(1, "duration", quantity(s.duration, "s"), fmt::format("{:g} h", s.duration / 3600.0));
  w.entry(1, "tolerance", quantity(s.tolerance, "m"));
  if (s.report_every > 0.0) w.entry(1, "report_every", quantity(s.report_every, "s"));
  w.entry(1, "failure_load", s.failure_load ? "true" : "false");
  if (!s.cycle) return;
  write_schedule(w, *s.cycle);
  w.entry(1, "relative_tolerance", quantity(s.cycle->march_tolerance, "1"));
}

}  // namespace

extern const StudySection kLifeKeys{.keys = kKeys, .read = read, .read_after_inputs = read_cycle, .write = write};

}  // namespace twb::scene_io
