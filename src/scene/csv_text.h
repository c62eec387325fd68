// A CSV file a scene names (a roughness profile, a rig's measurements): read whole, '#'
// comment lines and blank lines skipped, fields split at commas, and every fault an
// InputError at its line and column in the file.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/quantity.h"

namespace twb::scene_io {

struct CsvField {
  std::string text;
  std::size_t column = 0;  // 0-based offset of its first non-blank character
};

class CsvText {
 public:
  // Reads the regular file at `path` (at most max_bytes); `what` names it in messages
  // ("the roughness profile").
  CsvText(const std::string& path, std::string_view what, std::uintmax_t max_bytes);
  const std::string& path() const { return path_; }
  const std::vector<std::string>& lines() const { return lines_; }
  // line: 0-based index; column: 0-based offset in the line.
  [[noreturn]] void fail(std::size_t line, std::size_t column, const std::string& message) const;
  // A fault of the whole file (no line to point at).
  [[noreturn]] void fail(const std::string& message) const;
  // The first line at or after `line` that is neither blank nor a comment (lines().size()
  // where there is none).
  std::size_t next_row(std::size_t line) const;
  // The fields of a data row under a header of `columns` fields; a fault at the row where
  // it has another count.
  std::vector<CsvField> row(std::size_t line, std::size_t columns) const;
  // A field as a finite number; else a fault at it, naming it `column`.
  double number(std::size_t line, const CsvField& field, std::string_view column) const;

 private:
  std::string path_;
  std::vector<std::string> lines_;
};

// The line's fields, split at commas and trimmed.
std::vector<CsvField> csv_fields(const std::string& line);

// A header field's name and bracketed unit: "torque [N m]" -> {"torque", "N m"}; the
// unit empty where the field has no brackets, and `unit_column` its 0-based offset.
struct CsvHeader {
  std::string name, unit;
  std::size_t unit_column = 0;
};
CsvHeader csv_header(const CsvField& field);

// A column named the way the results tables name theirs, its unit in the name (load_N,
// ambient_C): what the reader takes it for (the reader's own code) and that unit.
struct ResultsName {
  std::string_view name;
  int what;
  std::string_view unit;
};
// A header field without brackets as one of `results`: its name's unit at the field's
// start (where a fault in it is shown); none where the field has brackets or is none of them.
std::optional<CsvHeader> results_header(const CsvField& field, std::span<const ResultsName> results, int& what);

// A column's unit as its conversion to SI, si = scale·v + offset (a temperature in degC
// has an offset); a fault at the unit's place where it is not of si_unit's kind.
struct UnitToSi {
  double scale = 1.0, offset = 0.0;
};
UnitToSi unit_to_si(const CsvText& text, std::size_t line, const CsvHeader& header, const SiUnit& si_unit);

}  // namespace twb::scene_io
