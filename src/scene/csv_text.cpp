#include "scene/csv_text.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "scene_source.h"
#include "twb/input_error.h"

namespace twb::scene_io {

CsvText::CsvText(const std::string& path, std::string_view what, std::uintmax_t max_bytes) : path_(path) {
  // Only a regular file: a device or a pipe named by mistake could be endless.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(path, 0, 0, fmt::format("cannot read {}: no such regular file", what), "");
  if (std::filesystem::file_size(path, error) > max_bytes)
    throw InputError(path, 0, 0, fmt::format("{} is larger than {} MB", what, max_bytes >> 20), "");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, 0, fmt::format("cannot read {} (is it readable?)", what), "");
  std::ostringstream content;
  content << in.rdbuf();
  std::string text = content.str();
  // A spreadsheet's "CSV UTF-8" starts with a byte-order mark, which is no part of the header.
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
  lines_ = split_lines(text);
}

void CsvText::fail(std::size_t line, std::size_t column, const std::string& message) const {
  throw InputError(path_, static_cast<int>(line) + 1, static_cast<int>(column) + 1, message, lines_[line]);
}

void CsvText::fail(const std::string& message) const { throw InputError(path_, 0, 0, message, ""); }

std::vector<CsvField> CsvText::row(std::size_t line, std::size_t columns) const {
  std::vector<CsvField> fields = csv_fields(lines_[line]);
  if (fields.size() != columns)
    fail(line, 0, fmt::format("this row has {} field{} and the header {} column{}: every row needs one field for each "
                              "column",
                              fields.size(), fields.size() == 1 ? "" : "s", columns, columns == 1 ? "" : "s"));
  return fields;
}

std::size_t CsvText::next_row(std::size_t line) const {
  for (; line < lines_.size(); ++line) {
    const std::size_t first = lines_[line].find_first_not_of(" \t\r");
    if (first != std::string::npos && lines_[line][first] != '#') return line;
  }
  return lines_.size();
}

double CsvText::number(std::size_t line, const CsvField& field, std::string_view column) const {
  const char* begin = field.text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (field.text.empty() || end != begin + field.text.size() || !std::isfinite(value))
    fail(line, field.column, fmt::format("the {} '{}' is not a finite number", column, field.text));
  return value;
}

std::vector<CsvField> csv_fields(const std::string& line) {
  std::vector<CsvField> fields;
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

CsvHeader csv_header(const CsvField& field) {
  CsvHeader h;
  const std::size_t open = field.text.find('['), close = field.text.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) {
    h.name = field.text;
    return h;
  }
  std::size_t name_end = open;
  while (name_end > 0 && std::isspace(static_cast<unsigned char>(field.text[name_end - 1]))) --name_end;
  h.name = field.text.substr(0, name_end);
  h.unit = field.text.substr(open + 1, close - open - 1);
  h.unit_column = field.column + open + 1;
  return h;
}

std::optional<CsvHeader> results_header(const CsvField& field, std::span<const ResultsName> results, int& what) {
  CsvHeader h = csv_header(field);
  if (!h.unit.empty()) return std::nullopt;
  for (const ResultsName& r : results)
    if (r.name == h.name) {
      what = r.what;
      h.unit = r.unit;
      h.unit_column = field.column;
      return h;
    }
  return std::nullopt;
}

UnitToSi unit_to_si(const CsvText& text, std::size_t line, const CsvHeader& header, const SiUnit& si_unit) {
  UnitToSi c;
  try {
    c.offset = to_si("0 " + header.unit, si_unit);
    c.scale = to_si("1 " + header.unit, si_unit) - c.offset;
  } catch (const QuantityError& e) {
    text.fail(line, header.unit_column, fmt::format("the {} column's unit '{}': {}", header.name, header.unit, e.what()));
  }
  return c;
}

}  // namespace twb::scene_io
