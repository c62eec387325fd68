// The files of a test that writes some: a directory of its own under the system's
// temporary directory (its process id in the name, so that the suites of two builds
// running at once do not share it), emptied first, and a file's whole text.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace twb::testing {

inline std::filesystem::path fresh_directory(const std::string& test, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("twb_" + test + "_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

inline std::string file_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace twb::testing
