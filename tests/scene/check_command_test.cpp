// `twb check FILE` on each malformed fixture: the CLI reports the InputError with its
// location on stderr and exits with status 2 (invalid input).
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "malformed_scenes.h"

namespace twb {
namespace {

struct ProcessResult {
  int status = -1;
  std::string err;
};

// Runs `twb check path` with stdout discarded and stderr captured.
ProcessResult check(const std::string& path) {
  const std::string command = std::string("'") + TWB_BINARY + "' check '" + path + "' 2>&1 >/dev/null";
  ProcessResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) result.err += buffer.data();
  const int status = pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

class CheckCommand : public ::testing::TestWithParam<testing::MalformedCase> {};

TEST_P(CheckCommand, MalformedSceneExitsWithStatus2AndItsLocation) {
  const testing::MalformedCase& c = GetParam();
  const std::string path = testing::malformed_path(c);
  const ProcessResult result = check(path);
  EXPECT_EQ(result.status, 2) << result.err;
  EXPECT_NE(result.err.find(path + ":" + std::to_string(c.line) + ":"), std::string::npos) << result.err;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, CheckCommand, ::testing::ValuesIn(testing::malformed_cases()),
                         [](const auto& info) { return info.param.name; });

TEST(CheckCommandPaperScene, ValidSceneExitsWithStatus0) {
  const ProcessResult result = check(testing::source_path("configs/jackson_green_2006.yaml"));
  EXPECT_EQ(result.status, 0) << result.err;
}

// What a sensitivity study's parameters or a map's axis may name: the inputs by their
// paths, with their SI values (docs/physics.md section 16).
TEST(CheckCommandPaperScene, ListsTheInputsByTheirPaths) {
  const std::string command =
      std::string("'") + TWB_BINARY + "' check '" + testing::source_path("configs/jackson_green_2006.yaml") + "'";
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) out += buffer.data();
  EXPECT_EQ(pclose(pipe), 0);
  EXPECT_NE(out.find("inputs (scene paths for a sensitivity study's parameters or a map's axis; SI):"), std::string::npos);
  EXPECT_NE(out.find("geometry.gear.tilt"), std::string::npos);
  EXPECT_NE(out.find(" 0.002 rad\n"), std::string::npos) << out;
  EXPECT_NE(out.find(" 545 rad/s\n"), std::string::npos);
}

}  // namespace
}  // namespace twb
