#include "twb/results/result_table.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace twb {

namespace {

// RFC 4180: a text cell holding a comma, a quote or a line break is quoted, quotes doubled.
std::string text_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string number_cell(double v, ResultColumn::Style style, int digits) {
  if (std::isnan(v)) return {};  // absent (put_number refuses any other non-finite value)
  switch (style) {
    case ResultColumn::Style::scientific:
      return fmt::format("{:.3e}", v);
    case ResultColumn::Style::fixed:
      return fmt::format("{:.3f}", v);
    case ResultColumn::Style::general:
      break;
  }
  return fmt::format("{:.{}g}", v, digits);
}

}  // namespace

ResultTable::Column ResultTable::number(std::string name, ResultColumn::Style style) {
  columns_.push_back({std::move(name), ResultColumn::Kind::number, style, {}, {}});
  return columns_.size() - 1;
}

ResultTable::Column ResultTable::count(std::string name) {
  columns_.push_back({std::move(name), ResultColumn::Kind::count, ResultColumn::Style::general, {}, {}});
  return columns_.size() - 1;
}

ResultTable::Column ResultTable::text(std::string name) {
  columns_.push_back({std::move(name), ResultColumn::Kind::text, ResultColumn::Style::general, {}, {}});
  return columns_.size() - 1;
}

void ResultTable::put_number(Column c, double value) {
  if (!std::isfinite(value)) throw std::runtime_error("non-finite result value for " + columns_.at(c).name);
  columns_.at(c).numbers.push_back(value);
}

void ResultTable::put_number(Column c, const std::optional<double>& value) {
  if (value)
    put_number(c, *value);
  else
    columns_.at(c).numbers.push_back(std::numeric_limits<double>::quiet_NaN());
}

void ResultTable::put_count(Column c, long long value) { columns_.at(c).numbers.push_back(double(value)); }

void ResultTable::put_text(Column c, std::string value) { columns_.at(c).texts.push_back(std::move(value)); }

std::size_t ResultTable::rows() const {
  if (columns_.empty()) return 0;
  const ResultColumn& c = columns_.front();
  return c.kind == ResultColumn::Kind::text ? c.texts.size() : c.numbers.size();
}

std::string ResultTable::csv(int significant_digits) const {
  std::string out;
  for (std::size_t k = 0; k < columns_.size(); ++k) out += (k ? "," : "") + columns_[k].name;
  out += "\n";
  const std::size_t n = rows();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < columns_.size(); ++k) {
      const ResultColumn& c = columns_[k];
      if (k) out += ",";
      switch (c.kind) {
        case ResultColumn::Kind::number:
          out += number_cell(c.numbers.at(i), c.style, significant_digits);
          break;
        case ResultColumn::Kind::count:
          out += fmt::format("{}", static_cast<long long>(c.numbers.at(i)));
          break;
        case ResultColumn::Kind::text:
          out += text_cell(c.texts.at(i));
          break;
      }
    }
    out += "\n";
  }
  return out;
}

}  // namespace twb
