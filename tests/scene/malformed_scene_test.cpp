// Every way a scene file can be wrong gets an exact, located error: one fixture per
// defect under tests/scene/data/malformed/, each a complete scene with one defect.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "malformed_scenes.h"
#include "scene_test_support.h"

namespace twb {
namespace {

class MalformedScene : public ::testing::TestWithParam<testing::MalformedCase> {};

TEST_P(MalformedScene, ErrorNamesTheLocationTheKeyAndWhatIsAllowed) {
  const testing::MalformedCase& c = GetParam();
  const std::string path = testing::malformed_path(c);
  const InputError error = testing::load_error(path);
  const std::string what = error.what();
  SCOPED_TRACE(what);
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.line(), c.line);
  if (c.column > 0) {
    EXPECT_EQ(error.column(), c.column);
  }
  for (const std::string& needle : c.message_contains)
    EXPECT_NE(what.find(needle), std::string::npos) << "missing: " << needle;

  // The diagnostic starts with the location, quotes the offending line, and puts the
  // caret under the column.
  const std::string location = c.column > 0
                                   ? path + ":" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": error: "
                                   : path + ":" + std::to_string(c.line) + ":";
  EXPECT_EQ(what.rfind(location, 0), 0u);
  const std::string gutter = std::to_string(c.line) + " | ";
  EXPECT_NE(what.find(gutter), std::string::npos);
  if (c.column > 0) {
    const std::size_t caret_line = what.rfind('\n');
    ASSERT_NE(caret_line, std::string::npos);
    const std::string caret = what.substr(caret_line + 1);
    EXPECT_EQ(caret.size(), std::string("      | ").size() + static_cast<std::size_t>(c.column));
    EXPECT_EQ(caret.back(), '^');
  }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, MalformedScene, ::testing::ValuesIn(testing::malformed_cases()),
                         [](const auto& info) { return info.param.name; });

// The fixtures directory and the table must agree, or a fixture would go untested.
TEST(MalformedSceneTable, CoversEveryFixture) {
  std::vector<std::string> listed;
  for (const auto& c : testing::malformed_cases()) listed.push_back(c.name + ".yaml");
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(testing::source_path("tests/scene/data/malformed"))) {
    ++files;
    EXPECT_NE(std::find(listed.begin(), listed.end(), entry.path().filename().string()), listed.end())
        << entry.path() << " has no row in malformed_scenes.h";
  }
  EXPECT_EQ(files, listed.size());
  EXPECT_GE(listed.size(), 30u);
}

}  // namespace
}  // namespace twb
