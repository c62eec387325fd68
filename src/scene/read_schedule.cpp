// A duty cycle's schedule (docs/scenes.md, study type duty_cycle; docs/physics.md
// section 19): the operating point at given times, in the scene
//   schedule:
//     - {t: 0 s, load: 100 N, speed: 3000 rpm}
//     - {t: 20 s, load: 300 N}               # the speed held: the point before's
//     - {t: 60 s, speed: 0 rpm, ambient: 90 degC, tilt: 1 mrad}
// or in a CSV file it names (`schedule: cycle.csv`), a header naming each column with its
// unit in brackets (t [s], load [N], speed [rpm], ambient [degC], tilt [mrad]) or by the
// results' own names (t_s, load_N, speed_rad_s, ambient_C, tilt_rad: a duty cycle's
// trajectory.csv is a schedule). A field a point leaves out (a key, an empty CSV field)
// is the point before's; the first point's is the scene's operating point and gear tilt.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scene/csv_text.h"
#include "scene/physical_bounds.h"
#include "scene/scene_source.h"
#include "scene_names.h"
#include "scene_sections.h"

namespace twb::scene_io {

namespace {

constexpr std::uintmax_t kMaxScheduleBytes = std::uintmax_t{64} << 20;
constexpr std::string_view kHeaderExample = "t [s], load [N], speed [rpm], ambient [degC], tilt [mrad]";

// A schedule's quantities, in SchedulePoint's order.
enum Quantity { kTime, kLoad, kSpeed, kAmbient, kTilt, kQuantities };
constexpr std::array<std::string_view, kQuantities> kKeys = {"t", "load", "speed", "ambient", "tilt"};
const SiUnit& unit_of(int q) {
  static const std::array<const SiUnit*, kQuantities> units = {&si::time, &si::force, &si::angular_speed,
                                                                &si::temperature, &si::angle};
  return *units[std::size_t(q)];
}

// The results' own column names, with their units.
constexpr ResultsName kResultsNames[] = {
    {"t_s", kTime, "s"},         {"load_N", kLoad, "N"},         {"speed_rad_s", kSpeed, "rad/s"},
    {"speed_rpm", kSpeed, "rpm"}, {"ambient_C", kAmbient, "degC"}, {"ambient_K", kAmbient, "K"},
    {"tilt_rad", kTilt, "rad"}};

// What each quantity may be. Unloaded, the washer lifts off its film and the gear goes to
// its stop at its axial play (docs/physics.md section 19): a load of zero needs one, and
// the film's pressure to lift the washer (with contact alone both films open until their
// asperities part, and nothing says how far each).
Range range_of(int q, const Scene& scene) {
  switch (q) {
    case kTime: return Range{.low = 0.0, .high = 1e9, .reason = "a time from 0 s, at most 1e9 s"};
    case kLoad:
      if (scene.gear.axial_play && scene.effects.hydrodynamics)
        return Range{.low = 0.0, .high = bounds::load.high,
                     .reason = "a load up to 1 MN; at zero the gear rests on its stop at geometry.gear.axial_play"};
      if (scene.gear.axial_play)
        return Range{.low = 0.0, .low_open = true, .high = bounds::load.high,
                     .reason = "a positive load up to 1 MN (a load of zero needs the hydrodynamics effect: with "
                               "asperity contact alone nothing holds the unloaded washer between its films, "
                               "docs/physics.md section 19)"};
      return Range{.low = 0.0, .low_open = true, .high = bounds::load.high,
                   .reason = "a positive load up to 1 MN (unloaded to zero, the washer lifts off its film and the "
                             "gear goes to its stop: give its axial play, geometry.gear.axial_play, "
                             "docs/physics.md section 19)"};
    case kSpeed:
      return Range{.low = -bounds::speed.high, .high = bounds::speed.high,
                   .reason = "a speed of at most 1e5 rad/s either way (negative: the washer turns back)"};
    case kAmbient:
      return scene.lubricant.viscosity_model == ViscosityModel::roelands ? bounds::roelands_temperature
                                                                          : bounds::absolute_temperature;
    default: return bounds::tilt;
  }
}

std::array<double, kQuantities> values_of(const SchedulePoint& p) {
  return {p.time, p.load, p.speed, p.ambient, p.tilt};
}
void set(SchedulePoint& p, int q, double v) {
  double* fields[kQuantities] = {&p.time, &p.load, &p.speed, &p.ambient, &p.tilt};
  *fields[q] = v;
}

// The point a schedule starts from before its first point says otherwise.
SchedulePoint operating_point(const Scene& scene) {
  SchedulePoint p;
  p.load = scene.operating.load;
  p.speed = scene.operating.speed;
  p.ambient = scene.operating.ambient;
  p.tilt = scene.gear.tilt;
  return p;
}

// Where a schedule cannot start: unloaded (its steady state is reached from a load), or
// the oil or a body already past its limit at the first point's ambient (every failure
// criterion of temperature is crossed before any heat).
std::optional<std::string> cannot_start_at(const SchedulePoint& first, const Scene& scene) {
  const auto degc = [](double k) { return k - 273.15; };
  if (first.load == 0.0)
    return "the schedule starts unloaded: the march starts from the steady state at its first point, which the "
           "steady solver reaches by raising the load from a fraction of it; start loaded (the scene's load, say) "
           "and unload within the cycle";
  if (first.ambient >= scene.lubricant.max_temperature)
    return fmt::format("the ambient {:.6g} degC at the schedule's start is past the oil's maximum temperature {:.6g} "
                       "degC (lubricant.max_temperature): the bearing has failed before the cycle begins",
                       degc(first.ambient), degc(scene.lubricant.max_temperature));
  if (first.ambient >= scene.lubricant.flash_temperature)
    return fmt::format("the ambient {:.6g} degC at the schedule's start is past the oil's flash point {:.6g} degC",
                       degc(first.ambient), degc(scene.lubricant.flash_temperature));
  const std::pair<const char*, const Component*> bodies[] = {
      {"carrier", &scene.carrier}, {"washer", &scene.washer}, {"gear", &scene.gear}};
  for (const auto& [name, body] : bodies)
    if (body->material.max_temperature && first.ambient >= *body->material.max_temperature)
      return fmt::format("the ambient {:.6g} degC at the schedule's start is past the {}'s material limit {:.6g} degC",
                         degc(first.ambient), name, degc(*body->material.max_temperature));
  return std::nullopt;
}

// Where a washer that came to rest with its load (the load reaching zero where the speed
// is zero, or with it) would leave the rest with its speed alone, the load still zero:
// none where none does. The gear came to rest off its stop, and nothing then bounds how
// fast the turning film lifts the washer, with nothing pressing it down (docs/physics.md
// section 19): the load must come back first, or with the speed.
std::optional<std::size_t> leaves_rest_unloaded(const std::vector<SchedulePoint>& points) {
  const auto at_rest = [](const SchedulePoint& p) { return p.load == 0.0 && p.speed == 0.0; };
  for (std::size_t k = 1; k + 1 < points.size(); ++k) {
    if (!at_rest(points[k]) || at_rest(points[k - 1]) || points[k - 1].load == 0.0) continue;
    std::size_t leave = k + 1;
    while (leave < points.size() && at_rest(points[leave])) ++leave;
    if (leave < points.size() && points[leave].load == 0.0) return leave;
  }
  return std::nullopt;
}

constexpr const char* kLeavesRestUnloaded =
    "the washer leaves a rest with its speed alone, still unloaded, after it came to rest with its load: the gear "
    "is off its stop there, and nothing then bounds how fast the turning film lifts the washer (docs/physics.md "
    "section 19); bring the load back first, or with the speed (a small load will do)";

std::string time_order_message(double time, double before) {
  return fmt::format("the times must increase strictly from point to point: {:.6g} s follows {:.6g} s (the inputs "
                     "are continuous in time; a step is a short ramp, two points a little apart)",
                     time, before);
}

std::vector<SchedulePoint> schedule_in_scene(const Node& list, const Scene& scene) {
  std::vector<SchedulePoint> points;
  SchedulePoint before = operating_point(scene);
  const std::vector<Node> items =
      list.list("a list of points, e.g. [{t: 0 s, load: 100 N, speed: 3000 rpm}, {t: 60 s, load: 300 N}], or the path "
                "of a CSV file");
  for (const Node& item : items) {
    const MapReader m(item, {std::begin(kKeys), std::end(kKeys)});
    m.get("t", "the point's time, e.g. 20 s");
    SchedulePoint p = before;
    for (int q = 0; q < kQuantities; ++q) {
      const double fallback = values_of(before)[std::size_t(q)];
      set(p, q, m.quantity(kKeys[std::size_t(q)], unit_of(q), range_of(q, scene), fallback));
    }
    p.file = item.origin() ? item.origin()->name : scene.source;
    p.line = item.mark().line + 1;
    if (!points.empty() && !(p.time > before.time)) {
      const Node t = m.get("t", "");
      t.fail(fmt::format("{}: {}", t.path(), time_order_message(p.time, before.time)));
    }
    points.push_back(p);
    before = p;
  }
  if (points.size() < 2)
    list.fail(fmt::format("{}: {} point{}: a cycle needs at least two, its start and its end", list.path(),
                          points.size(), points.size() == 1 ? "" : "s"));
  if (const std::optional<std::string> why = cannot_start_at(points.front(), scene))
    items.front().fail(fmt::format("{}: {}", items.front().path(), *why));
  if (const std::optional<std::size_t> k = leaves_rest_unloaded(points))
    items[*k].fail(fmt::format("{}: {}", items[*k].path(), kLeavesRestUnloaded));
  return points;
}

// A column of the schedule's CSV and its unit's conversion to SI (si = scale·v + offset).
struct Column {
  int what = -1;
  double scale = 1.0, offset = 0.0;
};

std::string allowed_names() {
  std::string names;
  for (std::string_view k : kKeys) names += fmt::format("{}{}", names.empty() ? "" : ", ", k);
  return names + " (t also as time)";
}

// `results`: the file is a results table (its time column is t_s), whose other columns
// (T_mean_C, regime, ...) a schedule does not read.
Column column_of(const CsvText& text, std::size_t line, const CsvField& field, bool results) {
  Column c;
  CsvHeader h = csv_header(field);
  if (h.unit.empty()) {
    const std::optional<CsvHeader> known = results_header(field, kResultsNames, c.what);
    if (!known && results) return c;  // not read
    if (!known)
      text.fail(line, field.column,
                fmt::format("the column '{}' gives no unit: name it {} with its unit in brackets, e.g. '{}'",
                            field.text, allowed_names(), kHeaderExample));
    h = *known;
  } else {
    const std::string name = h.name == "time" ? "t" : h.name;
    const auto k = std::find(kKeys.begin(), kKeys.end(), name);
    if (k == kKeys.end())
      text.fail(line, field.column,
                fmt::format("the column '{}' is none a schedule reads; the columns are {}", h.name, allowed_names()));
    c.what = int(k - kKeys.begin());
  }
  const UnitToSi to_si = unit_to_si(text, line, h, unit_of(c.what));
  c.scale = to_si.scale;
  c.offset = to_si.offset;
  return c;
}

std::vector<SchedulePoint> schedule_in_file(const std::string& path, const Scene& scene) {
  const CsvText text(path, "the schedule", kMaxScheduleBytes);
  const auto& lines = text.lines();
  std::size_t k = text.next_row(0);
  if (k == lines.size())
    text.fail(fmt::format("the schedule is empty: it needs a header such as '{}' and then one row a point in time",
                          kHeaderExample));
  const std::vector<CsvField> header = csv_fields(lines[k]);
  std::vector<Column> columns;
  std::array<std::optional<std::size_t>, kQuantities> seen;
  const bool results = std::any_of(header.begin(), header.end(), [](const CsvField& f) { return f.text == "t_s"; });
  for (std::size_t c = 0; c < header.size(); ++c) {
    columns.push_back(column_of(text, k, header[c], results));
    if (columns.back().what < 0) continue;
    std::optional<std::size_t>& first = seen[std::size_t(columns.back().what)];
    if (first)
      text.fail(k, header[c].column, fmt::format("a second {} column (the first is column {})",
                                                 kKeys[std::size_t(columns.back().what)], *first + 1));
    first = c;
  }
  if (!seen[kTime])
    text.fail(k, 0, fmt::format("no time column: every point of a schedule needs its time, e.g. '{}'", kHeaderExample));

  std::vector<SchedulePoint> points;
  SchedulePoint before = operating_point(scene);
  for (k = text.next_row(k + 1); k < lines.size(); k = text.next_row(k + 1)) {
    const std::vector<CsvField> row = text.row(k, header.size());
    SchedulePoint p = before;
    p.file = path;
    p.line = int(k) + 1;
    for (std::size_t c = 0; c < row.size(); ++c) {
      const Column& col = columns[c];
      if (col.what < 0) continue;
      const std::string_view name = kKeys[std::size_t(col.what)];
      if (row[c].text.empty()) {
        if (col.what == kTime) text.fail(k, row[c].column, "the time is empty: every point needs its time");
        continue;  // the point before's
      }
      const double value = col.scale * text.number(k, row[c], name) + col.offset;
      const Range range = range_of(col.what, scene);
      if (!range.contains(value))
        text.fail(k, row[c].column,
                  fmt::format("the {} '{}' ({:.6g} {} in SI) is out of range; must be {} {}{}", name, row[c].text, value,
                              unit_of(col.what).symbol, range.describe(), unit_of(col.what).symbol,
                              range.reason.empty() ? "" : fmt::format(" ({})", range.reason)));
      set(p, col.what, value);
    }
    if (!points.empty() && !(p.time > before.time)) {
      // A trajectory's steps may lie closer than its ten digits tell apart: the first of
      // them stands for all.
      if (results && p.time == before.time) continue;
      text.fail(k, row[*seen[kTime]].column, time_order_message(p.time, before.time));
    }
    if (points.empty())
      if (const std::optional<std::string> why = cannot_start_at(p, scene)) text.fail(k, 0, *why);
    points.push_back(p);
    before = p;
  }
  if (points.size() < 2)
    text.fail(fmt::format("the schedule has {} point{}: a cycle needs at least two, its start and its end",
                          points.size(), points.size() == 1 ? "" : "s"));
  if (const std::optional<std::size_t> at = leaves_rest_unloaded(points))
    text.fail(std::size_t(points[*at].line - 1), 0, kLeavesRestUnloaded);
  return points;
}

}  // namespace

Node read_schedule_into(const MapReader& scene, Scene& out, DutyCycleSettings& s) {
  const MapReader study = scene.map("study", {std::begin(kStudyKeys), std::end(kStudyKeys)});
  const Node schedule = study.get("schedule", "a list of points, e.g. [{t: 0 s, load: 100 N, speed: 3000 rpm}, "
                                              "{t: 60 s, load: 300 N}], or the path of a CSV file");
  if (!schedule.yaml().IsScalar()) {
    s.schedule = schedule_in_scene(schedule, out);
    return schedule;
  }
  s.schedule_file = named_file_path(schedule, "the path of a schedule file (CSV), e.g. cycle.csv");
  // A file that is not there is a fault of the scene, at its key; what is wrong inside
  // one is located in it.
  std::error_code error;
  if (!std::filesystem::is_regular_file(s.schedule_file, error))
    schedule.fail(fmt::format("{}: cannot read the schedule '{}': no such regular file (a path relative to the scene "
                              "file's directory)",
                              schedule.path(), s.schedule_file));
  s.schedule = schedule_in_file(s.schedule_file, out);
  return schedule;
}

void read_schedule(const MapReader& scene, Scene& out) {
  read_schedule_into(scene, out, std::get<DutyCycleSettings>(out.study.settings));
}

void check_marched_in_real_time(const MapReader& study, const Scene& scene, std::string_view what) {
  const Node type = study.get("type", "");
  if (!scene.effects.thermal)
    type.fail(fmt::format("{}: {} marches the bodies' heat in time (docs/physics.md section 19), so it needs the "
                          "thermal effect; add 'thermal' to effects",
                          type.path(), what));
  if (scene.effects.hydrodynamics && scene.effects.cavitation == CavitationModel::jfo)
    type.fail(fmt::format("{}: {} solves the film's squeeze (docs/physics.md section 19) with the Reynolds "
                          "cavitation condition only: the mass-conserving model's film content would be a "
                          "differential unknown held at 1 wherever the film is full (a DAE of index two, not "
                          "solved); use hydrodynamics: {{cavitation: reynolds}}",
                          type.path(), what));
}

}  // namespace twb::scene_io
