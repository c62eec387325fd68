// The scene file as describe_scene writes it: values as the shortest text that reads back
// to the same double with their SI unit, strings quoted, keys indented by section.
#pragma once

#include <string>
#include <string_view>

#include <fmt/format.h>

namespace twb::scene_io {

// Shortest text that parses back to the same double, then the SI unit.
inline std::string quantity(double value, std::string_view unit) {
  return unit == "1" ? fmt::format("{}", value) : fmt::format("{} {}", value, unit);
}

// A YAML double-quoted string. Control characters are escaped: a raw line break would be
// folded into a space when the text is read back, and most others may not appear in YAML.
inline std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    const auto code = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (code < 0x20 || code == 0x7f) {
      out += fmt::format("\\x{:02x}", code);
    } else {
      out += c;
    }
  }
  return out + "\"";
}

class SceneText {
 public:
  void line(int indent, std::string_view text) {
    out_ += std::string(static_cast<std::size_t>(2 * indent), ' ');
    out_ += text;
    out_ += '\n';
  }
  void entry(int indent, std::string_view key, const std::string& value, std::string_view comment = {}) {
    line(indent, comment.empty() ? fmt::format("{}: {}", key, value)
                                 : fmt::format("{}: {}  # {}", key, value, comment));
  }
  std::string text() && { return std::move(out_); }

 private:
  std::string out_;
};

}  // namespace twb::scene_io
