#include "roughness_profile.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "scene/csv_text.h"
#include "twb/input_error.h"
#include "scene/quantity.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kHeaderExample = "x [um], z [um]";

// The factor from a header field's bracketed unit to metres.
double unit_factor(const CsvText& text, std::size_t line, const CsvField& field, std::string_view column) {
  const CsvHeader header = csv_header(field);
  if (header.unit.empty())
    text.fail(line, field.column,
              fmt::format("the {} column's header '{}' gives no unit: write its unit in brackets, e.g. '{}'",
                          column, field.text, kHeaderExample));
  try {
    return to_si("1 " + header.unit, si::length);
  } catch (const QuantityError& e) {
    text.fail(line, header.unit_column, fmt::format("the {} column's unit '{}': {}", column, header.unit, e.what()));
  }
}

}  // namespace

RoughnessProfile read_roughness_profile(const std::string& path) {
  const CsvText text(path, "the roughness profile", kMaxProfileBytes);
  const auto& lines = text.lines();

  std::size_t k = text.next_row(0);
  if (k == lines.size())
    throw InputError(path, 0, 0, fmt::format("the profile is empty: it needs a header such as '{}' "
                                             "and then position, height rows", kHeaderExample), "");
  const std::vector<CsvField> header = csv_fields(lines[k]);
  if (header.size() != 2)
    text.fail(k, 0, fmt::format("the header has {} columns; a profile has two, position and height, "
                                "each with its unit, e.g. '{}'", header.size(), kHeaderExample));
  const double x_unit = unit_factor(text, k, header[0], "position");
  const double z_unit = unit_factor(text, k, header[1], "height");

  std::vector<double> x;
  std::vector<std::size_t> row_line;
  RoughnessProfile profile;
  for (k = text.next_row(k + 1); k < lines.size(); k = text.next_row(k + 1)) {
    const std::vector<CsvField> row = csv_fields(lines[k]);
    if (row.size() != 2)
      text.fail(k, 0, fmt::format("a row has two numbers, position and height; this one has {} fields",
                                  row.size()));
    x.push_back(text.number(k, row[0], "position") * x_unit);
    profile.heights.push_back(text.number(k, row[1], "height") * z_unit);
    row_line.push_back(k);
  }
  const std::size_t n = x.size();
  if (n < static_cast<std::size_t>(kMinProfileSamples))
    throw InputError(path, 0, 0,
                     fmt::format("the profile has {} heights; the summit statistics need at least {} "
                                 "(a measured trace has thousands)", n, kMinProfileSamples), "");
  profile.spacing = (x[n - 1] - x[0]) / static_cast<double>(n - 1);
  if (!(profile.spacing > 0))
    text.fail(row_line[n - 1], 0, "the positions must increase from the first row to the last");
  // A file written with a few digits rounds the positions; one part in a thousand of
  // the spacing is far more than rounding and far less than a missing sample.
  for (std::size_t i = 1; i < n; ++i) {
    const double step = x[i] - x[i - 1];
    if (std::abs(step - profile.spacing) > 1e-3 * profile.spacing)
      text.fail(row_line[i], 0,
                fmt::format("the heights must be at uniform spacing: this row is {:.6g} m after the one "
                            "before, the mean spacing is {:.6g} m (a missing or repeated sample?)",
                            step, profile.spacing));
  }
  return profile;
}

}  // namespace twb::scene_io
