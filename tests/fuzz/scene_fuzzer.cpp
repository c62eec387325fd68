// libFuzzer target for the scene loader and the `--set` parser. An input is the text of a
// scene file; each of its lines "#--set path=value" is also given to the loader as an
// override. Those lines are YAML comments, so a corpus file stays a readable scene and a
// mutation lands in the file or in an override alike.
//
// Every input must end in a Scene or in an InputError that points into the input: any
// other exception, a crash, a hang or a sanitizer report is a finding.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "twb/input_error.h"
#include "twb/scene/scene_loader.h"

namespace {

constexpr std::string_view kOverridePrefix = "#--set ";
constexpr const char* kName = "fuzz.yaml";

std::vector<std::string> overrides_in(const std::string& text) {
  std::vector<std::string> overrides;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string_view line(text.data() + start, end - start);
    if (line.substr(0, kOverridePrefix.size()) == kOverridePrefix)
      overrides.emplace_back(line.substr(kOverridePrefix.size()));
    start = end + 1;
  }
  return overrides;
}

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "scene_fuzzer finding: %s\n", what.c_str());
  std::abort();
}

// A user can only act on an error that points into what they wrote.
void check_located(const twb::InputError& error, const std::string& text) {
  const auto lines = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
  const bool names_file = error.file() == kName;
  const bool names_override = error.file().rfind("--set", 0) == 0;
  const std::string what = error.what();
  // A roughness profile the input names is a file of its own, its errors located in it.
  if (!names_file && !names_override &&
      (error.message().find("profile") != std::string::npos || std::filesystem::exists(error.file())))
    return;
  if (!names_file && !names_override) finding("InputError names neither the file nor an override:\n" + what);
  if (error.line() < 0 || error.column() < 0) finding("InputError with a negative location:\n" + what);
  if (error.line() > lines) finding("InputError past the file's last line:\n" + what);
  if (names_override && error.line() != 0) finding("InputError puts an override on a line:\n" + what);
}

// describe_scene promises text that loads back to the same scene; describing that again
// must give the same text, apart from the header comments naming the source.
void check_description_round_trip(const twb::Scene& scene) {
  const auto body = [](const std::string& text) { return text.substr(text.find("\neffects:")); };
  const std::string described = twb::describe_scene(scene);
  try {
    const twb::Scene again = twb::load_scene_text(described, "described.yaml");
    if (body(twb::describe_scene(again)) != body(described))
      finding("describing the described scene changes it:\n" + described);
  } catch (const twb::InputError& error) {
    finding("the described scene does not load back:\n" + std::string(error.what()) + "\n" + described);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    check_description_round_trip(twb::load_scene_text(text, kName, overrides_in(text)));
  } catch (const twb::InputError& error) {
    check_located(error, text);
  } catch (const std::exception& error) {
    finding(std::string("an exception other than InputError escaped: ") + error.what());
  } catch (...) {
    finding("an exception that is not a std::exception escaped");
  }
  return 0;
}
