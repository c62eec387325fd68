#include "scene_source.h"

#include "twb/input_error.h"

namespace twb::scene_io {

void fail_at(const Origin& origin, const YAML::Mark& mark, bool at_key, const std::string& message) {
  const bool has_mark = mark.line >= 0 && mark.column >= 0;
  const std::string excerpt = origin.lines.empty() ? std::string() : origin.lines.front();
  if (!origin.is_file) {
    // An override is one line of text; yaml-cpp's marks count from its value.
    const int column = at_key || !has_mark ? origin.key_column : origin.value_column + mark.column;
    throw InputError(origin.name, 0, column, message, excerpt);
  }
  if (!has_mark) throw InputError(origin.name, 0, 0, message, "");
  const auto line = static_cast<std::size_t>(mark.line);
  throw InputError(origin.name, mark.line + 1, mark.column + 1, message,
                   line < origin.lines.size() ? origin.lines[line] : std::string());
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

}  // namespace twb::scene_io
