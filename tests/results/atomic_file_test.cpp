// Results are written atomically: the target holds either the old or the new content,
// never a partial file, and no temporary file is left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "results/atomic_file.h"

namespace twb {
namespace {

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AtomicFile, WritesReplacesAndLeavesNoTemporary) {
  const auto dir = std::filesystem::temp_directory_path() / "twb_atomic_file_test" / "nested";
  std::filesystem::remove_all(dir.parent_path());
  const auto target = dir / "states.csv";
  write_file_atomically(target, "first\n");
  EXPECT_EQ(read(target), "first\n");
  write_file_atomically(target, "second, longer content\n");
  EXPECT_EQ(read(target), "second, longer content\n");
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    ++entries;
    EXPECT_EQ(e.path().filename(), "states.csv") << "left behind: " << e.path();
  }
  EXPECT_EQ(entries, 1);
  std::filesystem::remove_all(dir.parent_path());
}

TEST(AtomicFile, UnwritableTargetThrowsAndKeepsTheOldFile) {
  const auto dir = std::filesystem::temp_directory_path() / "twb_atomic_file_test2";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "states.csv");  // a directory where the file should go
  EXPECT_THROW(write_file_atomically(dir / "states.csv", "x"), std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "states.csv"));
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1) << "the temporary file must be removed on failure";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace twb
