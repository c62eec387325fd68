#include "twb/input_error.h"

#include <fmt/format.h>

namespace twb {
namespace {

// Compiler-style diagnostics ("file:line:column: error: ..." then the line with a caret)
// because editors and terminals already know how to jump to them.
std::string format_diagnostic(const std::string& file, int line, int column,
                              const std::string& message, const std::string& excerpt) {
  std::string out;
  if (line > 0 && column > 0) {
    out = fmt::format("{}:{}:{}: error: {}", file, line, column, message);
  } else if (line > 0) {
    out = fmt::format("{}:{}: error: {}", file, line, message);
  } else {
    out = fmt::format("{}: error: {}", file, message);
  }
  if (excerpt.empty()) return out;

  const std::string gutter = line > 0 ? fmt::format("{:>5}", line) : std::string(5, ' ');
  out += fmt::format("\n{} | {}", gutter, excerpt);
  if (column > 0) {
    // Keep tabs in the padding so the caret lines up under tab-indented text.
    std::string pad;
    for (std::size_t i = 0; i + 1 < static_cast<std::size_t>(column); ++i)
      pad += i < excerpt.size() && excerpt[i] == '\t' ? '\t' : ' ';
    out += fmt::format("\n{} | {}^", std::string(gutter.size(), ' '), pad);
  }
  return out;
}

}  // namespace

InputError::InputError(std::string file, int line, int column, std::string message,
                       std::string excerpt)
    : std::runtime_error(format_diagnostic(file, line, column, message, excerpt)),
      file_(std::move(file)),
      line_(line),
      column_(column),
      message_(std::move(message)) {}

}  // namespace twb
