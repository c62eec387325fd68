// The error family's member (twb/error_family.h) for anything that came from a scene
// file, a file it names or a `--set` override: it knows where the offending text is and
// quotes it, so a user can fix the input without reading the loader.
#pragma once

#include <stdexcept>
#include <string>

namespace twb {

class InputError : public std::runtime_error {
 public:
  // file: path of the scene file, or "--set a.b" for an override.
  // line, column: 1-based; line 0 means the location is not a line of a file (an
  // override, or a whole file), column 0 means no caret.
  // excerpt: the quoted source line (or override text); empty for none.
  InputError(std::string file, int line, int column, std::string message, std::string excerpt);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  // The message alone, without location and excerpt.
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  int column_;
  std::string message_;
};

}  // namespace twb
