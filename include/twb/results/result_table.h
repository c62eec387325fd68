// A results table as columns of one type each: what a CSV file of the results directory
// holds and what the Python module hands over (as arrays), built once so that both carry
// the same numbers under the same names. Numbers are SI except where the column's name
// says otherwise (_C); a value that does not exist (no fold found, no parameter) is
// absent: an empty CSV cell, NaN in an array. A non-finite value that is not marked
// absent is a bug upstream and throws, so results never carry NaN or infinity.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace twb {

struct ResultColumn {
  enum class Kind { number, count, text };
  // How a number is written in CSV: {:.10g} (or more digits, csv()), {:.3e} (residuals),
  // {:.3f} (milliseconds).
  enum class Style { general, scientific, fixed };
  std::string name;
  Kind kind = Kind::number;
  Style style = Style::general;
  std::vector<double> numbers;     // number (NaN: absent), count
  std::vector<std::string> texts;  // text
};

class ResultTable {
 public:
  using Column = std::size_t;
  Column number(std::string name, ResultColumn::Style style = ResultColumn::Style::general);
  Column count(std::string name);
  Column text(std::string name);

  // Throws std::runtime_error naming the column for a non-finite value.
  void put_number(Column c, double value);
  void put_number(Column c, const std::optional<double>& value);  // nullopt: absent
  void put_count(Column c, long long value);
  void put_text(Column c, std::string value);

  const std::vector<ResultColumn>& columns() const { return columns_; }
  // Rows: the length of the first column (every column gets one cell per row).
  std::size_t rows() const;
  // Header line, then one line per row; text cells quoted as RFC 4180 asks where needed.
  // Numbers of the general style with `significant_digits` (17: each reads back as the
  // same double; twb run --full-precision).
  std::string csv(int significant_digits = 10) const;

 private:
  std::vector<ResultColumn> columns_;
};

}  // namespace twb
