#include "roughness_profile.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "scene_source.h"
#include "twb/scene/input_error.h"
#include "scene/quantity.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kHeaderExample = "x [um], z [um]";

class ProfileText {
 public:
  ProfileText(std::string path, std::vector<std::string> lines) : path_(std::move(path)), lines_(std::move(lines)) {}
  const std::vector<std::string>& lines() const { return lines_; }
  // line: 0-based index; column: 0-based offset in the line.
  [[noreturn]] void fail(std::size_t line, std::size_t column, const std::string& message) const {
    throw InputError(path_, static_cast<int>(line) + 1, static_cast<int>(column) + 1, message, lines_[line]);
  }

 private:
  std::string path_;
  std::vector<std::string> lines_;
};

struct Field {
  std::string text;
  std::size_t column = 0;  // of its first non-blank character
};

std::vector<Field> split_fields(const std::string& line) {
  std::vector<Field> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string::npos ? line.size() : comma;
    std::size_t first = start, last = end;
    while (first < last && std::isspace(static_cast<unsigned char>(line[first]))) ++first;
    while (last > first && std::isspace(static_cast<unsigned char>(line[last - 1]))) --last;
    fields.push_back({line.substr(first, last - first), first});
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

bool skipped(const std::string& line) {
  const std::size_t first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

// The factor from a header field's bracketed unit to metres.
double unit_factor(const ProfileText& text, std::size_t line, const Field& field, std::string_view column) {
  const std::size_t open = field.text.find('['), close = field.text.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open)
    text.fail(line, field.column,
              fmt::format("the {} column's header '{}' gives no unit: write its unit in brackets, e.g. '{}'",
                          column, field.text, kHeaderExample));
  const std::string unit = field.text.substr(open + 1, close - open - 1);
  try {
    return to_si("1 " + unit, si::length);
  } catch (const QuantityError& e) {
    text.fail(line, field.column + open + 1,
              fmt::format("the {} column's unit '{}': {}", column, unit, e.what()));
  }
}

double number(const ProfileText& text, std::size_t line, const Field& field, std::string_view column) {
  const char* begin = field.text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (field.text.empty() || end != begin + field.text.size() || !std::isfinite(value))
    text.fail(line, field.column,
              fmt::format("the {} '{}' is not a finite number", column, field.text));
  return value;
}

}  // namespace

RoughnessProfile read_roughness_profile(const std::string& path) {
  // Only a regular file: a device or a pipe named by mistake could be endless.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(path, 0, 0, "cannot read the roughness profile: no such regular file", "");
  if (std::filesystem::file_size(path, error) > kMaxProfileBytes)
    throw InputError(path, 0, 0, fmt::format("the roughness profile is larger than {} MB; a trace of a "
                                             "million heights needs about 20", kMaxProfileBytes >> 20), "");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, 0, "cannot read the roughness profile file (is it readable?)", "");
  std::ostringstream content;
  content << in.rdbuf();
  const ProfileText text(path, split_lines(content.str()));
  const auto& lines = text.lines();

  std::size_t k = 0;
  while (k < lines.size() && skipped(lines[k])) ++k;
  if (k == lines.size())
    throw InputError(path, 0, 0, fmt::format("the profile is empty: it needs a header such as '{}' "
                                             "and then position, height rows", kHeaderExample), "");
  const std::vector<Field> header = split_fields(lines[k]);
  if (header.size() != 2)
    text.fail(k, 0, fmt::format("the header has {} columns; a profile has two, position and height, "
                                "each with its unit, e.g. '{}'", header.size(), kHeaderExample));
  const double x_unit = unit_factor(text, k, header[0], "position");
  const double z_unit = unit_factor(text, k, header[1], "height");

  std::vector<double> x;
  std::vector<std::size_t> row_line;
  RoughnessProfile profile;
  for (++k; k < lines.size(); ++k) {
    if (skipped(lines[k])) continue;
    const std::vector<Field> row = split_fields(lines[k]);
    if (row.size() != 2)
      text.fail(k, 0, fmt::format("a row has two numbers, position and height; this one has {} fields",
                                  row.size()));
    x.push_back(number(text, k, row[0], "position") * x_unit);
    profile.heights.push_back(number(text, k, row[1], "height") * z_unit);
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
