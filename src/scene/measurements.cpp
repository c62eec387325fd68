#include "scene/measurements.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "scene/csv_text.h"
#include "scene_names.h"
#include "twb/input_error.h"

namespace twb::scene_io {

namespace {

constexpr std::uintmax_t kMaxDataBytes = std::uintmax_t{64} << 20;
constexpr std::string_view kHeaderExample = "load [N], speed [rpm], torque [N m], T_mean [degC]";

// A column: the load, the speed or a measured quantity, and its unit's conversion to SI
// (si = scale·v + offset: a temperature in degC has an offset).
struct Column {
  int what = -1;  // 0..3: MeasuredQuantity; kLoad, kSpeed, kAmbient; kSd + q: a reading's standard deviation
  double scale = 1.0, offset = 0.0;
};
constexpr int kLoad = 10, kSpeed = 11, kAmbient = 12, kSd = 13, kWhats = kSd + int(kMeasuredQuantities);
bool is_sd(int what) { return what >= kSd; }

// The results' own column names, with their units.
constexpr ResultsName kResultsNames[] = {
    {"load_N", kLoad, "N"},         {"speed_rad_s", kSpeed, "rad/s"}, {"speed_rpm", kSpeed, "rpm"},
    {"torque_Nm", 0, "N m"},        {"f_eff", 1, "1"},                {"T_mean_C", 2, "degC"},
    {"T_mean_K", 2, "K"},           {"T_max_C", 3, "degC"},           {"T_max_K", 3, "K"},
    {"ambient_C", kAmbient, "degC"}, {"ambient_K", kAmbient, "K"},
    {"f_eff_sd", kSd + int(MeasuredQuantity::f_eff), "1"}};  // a ratio's spread, as f_eff, needs no unit

const SiUnit& unit_of(int what) {
  if (is_sd(what)) what -= kSd;
  if (what == kLoad) return si::force;
  if (what == kSpeed) return si::angular_speed;
  if (what == kAmbient) return si::temperature;
  if (what == 0) return si::torque;
  if (what == 1) return si::dimensionless;
  return si::temperature;
}

std::string allowed_names() {
  std::string names = "load, speed, ambient";
  for (std::string_view n : kMeasuredNames) names += fmt::format(", {}", n);
  for (std::string_view n : kMeasuredNames) names += fmt::format(", {}_sd", n);
  return names;
}

Column column_of(const CsvText& text, std::size_t line, const CsvField& field) {
  Column c;
  CsvHeader h = csv_header(field);
  if (h.unit.empty()) {
    const std::optional<CsvHeader> known = results_header(field, kResultsNames, c.what);
    if (!known)
      text.fail(line, field.column,
                fmt::format("the column '{}' gives no unit: name it {} with its unit in brackets, e.g. '{}'",
                            field.text, allowed_names(), kHeaderExample));
    h = *known;
  } else if (h.name == "load") {
    c.what = kLoad;
  } else if (h.name == "speed") {
    c.what = kSpeed;
  } else if (h.name == "ambient") {
    c.what = kAmbient;
  } else {
    const bool sd = h.name.size() > 3 && h.name.ends_with("_sd");
    const std::string quantity = sd ? h.name.substr(0, h.name.size() - 3) : h.name;
    const auto q = std::find(std::begin(kMeasuredNames), std::end(kMeasuredNames), quantity);
    if (q == std::end(kMeasuredNames))
      text.fail(line, field.column,
                fmt::format("the column '{}' is none a calibration reads; the columns are {}", h.name, allowed_names()));
    c.what = int(q - std::begin(kMeasuredNames)) + (sd ? kSd : 0);
  }
  const UnitToSi to_si = unit_to_si(text, line, h, unit_of(c.what));
  c.scale = to_si.scale;
  // A spread is a difference: a temperature's in degC is one in K (no offset).
  c.offset = is_sd(c.what) ? 0.0 : to_si.offset;
  return c;
}

std::string name_of(int what) {
  if (what == kLoad) return "load";
  if (what == kSpeed) return "speed";
  if (what == kAmbient) return "ambient";
  if (is_sd(what)) return std::string(kMeasuredNames[std::size_t(what - kSd)]) + "_sd";
  return std::string(kMeasuredNames[std::size_t(what)]);
}

}  // namespace

std::vector<MeasuredPoint> read_measurements(const std::string& path) {
  const CsvText text(path, "the measurements", kMaxDataBytes);
  const auto& lines = text.lines();
  std::size_t k = text.next_row(0);
  if (k == lines.size())
    text.fail(fmt::format("the measurements are empty: they need a header such as '{}' and then one row a "
                          "measured point",
                          kHeaderExample));
  const std::vector<CsvField> header = csv_fields(lines[k]);
  std::vector<Column> columns;
  std::optional<std::size_t> seen[kWhats];
  for (std::size_t c = 0; c < header.size(); ++c) {
    columns.push_back(column_of(text, k, header[c]));
    std::optional<std::size_t>& first = seen[columns.back().what];
    if (first)
      text.fail(k, header[c].column, fmt::format("a second {} column (the first is column {})",
                                                 name_of(columns.back().what), *first + 1));
    first = c;
  }
  for (const int needed : {kLoad, kSpeed})
    if (!seen[needed])
      text.fail(k, 0, fmt::format("no {} column: every measured point needs its load and speed, e.g. '{}'",
                                  name_of(needed), kHeaderExample));
  for (std::size_t q = 0; q < kMeasuredQuantities; ++q)
    if (const std::optional<std::size_t>& sd = seen[kSd + int(q)]; sd && !seen[q])
      text.fail(k, header[*sd].column,
                fmt::format("a {}_sd column without a {} column: a standard deviation belongs to its readings",
                            kMeasuredNames[q], kMeasuredNames[q]));
  if (std::none_of(seen, seen + kMeasuredQuantities, [](const auto& s) { return s.has_value(); }))
    text.fail(k, 0, fmt::format("no measured quantity: give at least one of torque, f_eff, T_mean, T_max, e.g. '{}'",
                                kHeaderExample));

  std::vector<MeasuredPoint> points;
  for (k = text.next_row(k + 1); k < lines.size(); k = text.next_row(k + 1)) {
    const std::vector<CsvField> row = text.row(k, header.size());
    MeasuredPoint& p = points.emplace_back();
    p.values.fill(std::numeric_limits<double>::quiet_NaN());
    p.sd.fill(std::numeric_limits<double>::quiet_NaN());
    p.line = int(k) + 1;
    bool measured = false;
    for (std::size_t c = 0; c < row.size(); ++c) {
      const Column& col = columns[c];
      const std::string name = name_of(col.what);
      if (is_sd(col.what)) {
        // With a quantity's sd column, each of its readings carries its own.
        const std::size_t q = std::size_t(col.what - kSd);
        const bool read = !row[*seen[q]].text.empty();
        if (row[c].text.empty() != !read)
          text.fail(k, row[c].column,
                    read ? fmt::format("the {} reading has no standard deviation: with a {} column every reading of "
                                       "{} gives its own",
                                       kMeasuredNames[q], name, kMeasuredNames[q])
                         : fmt::format("a standard deviation for no {} reading: leave the field empty where the "
                                       "point does not measure {}",
                                       kMeasuredNames[q], kMeasuredNames[q]));
        if (!read) continue;
        const double sd = col.scale * text.number(k, row[c], name);
        if (!(sd > 0.0))
          text.fail(k, row[c].column, fmt::format("the {} '{}' must be positive", name, row[c].text));
        p.sd[q] = sd;
        continue;
      }
      // A quantity not measured here; the scene's ambient where the point gives none.
      if (row[c].text.empty() && (col.what < int(kMeasuredQuantities) || col.what == kAmbient)) continue;
      const double value = col.scale * text.number(k, row[c], name) + col.offset;
      const bool positive =
          col.what == kLoad || col.what == kSpeed || col.what == kAmbient || col.what == 2 || col.what == 3;
      if (positive ? !(value > 0.0) : !(value >= 0.0))
        text.fail(k, row[c].column,
                  fmt::format("the {} '{}' must be {} ({:.6g} {} in SI)", name, row[c].text,
                              positive ? "positive" : "zero or more", value, unit_of(col.what).symbol));
      if (col.what == kLoad) p.load = value;
      else if (col.what == kSpeed) p.speed = value;
      else if (col.what == kAmbient) p.ambient = value;
      else {
        p.values[std::size_t(col.what)] = value;
        measured = true;
      }
    }
    if (!measured) text.fail(k, 0, "the row measures nothing: every quantity's field is empty");
  }
  if (points.empty())
    text.fail(fmt::format("the measurements have a header but no rows: one row a measured point, e.g. under '{}' "
                          "a row '150, 3000, 0.121, 94.2'",
                          kHeaderExample));
  return points;
}

}  // namespace twb::scene_io
