// Results are written atomically: the target holds either the old or the new content,
// never a partial file, and no temporary file is left behind.
#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "results/atomic_file.h"
#include "twb/error_family.h"

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
  try {
    write_file_atomically(dir / "states.csv", "x");
    ADD_FAILURE() << "a file written over a directory";
  } catch (const IoError& e) {
    EXPECT_EQ(e.path(), (dir / "states.csv").string());
    EXPECT_NE(std::string(e.what()).find("cannot move into place"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_directory(dir / "states.csv"));
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1) << "the temporary file must be removed on failure";
  std::filesystem::remove_all(dir);
}

// A path under a regular file fails for root too (unlike a directory without write
// permission, which CI's root writes into): the I/O error of the family, naming the path
// and the system's reason, and no request to report a bug.
TEST(AtomicFile, APathUnderAFileIsAnIoErrorNamingIt) {
  const auto file = std::filesystem::temp_directory_path() / "twb_atomic_file_test3";
  std::filesystem::remove_all(file);
  std::ofstream(file) << "a file, not a directory";
  const auto target = file / "results" / "states.csv";
  try {
    write_file_atomically(target, "x");
    ADD_FAILURE() << "written under a file";
  } catch (const IoError& e) {
    EXPECT_EQ(e.error_number(), ENOTDIR);
    const ErrorReport report = report_error(std::current_exception());
    EXPECT_EQ(report.kind, ErrorKind::io);
    EXPECT_EQ(report.exit_status(), 5);
    EXPECT_EQ(report.message, "twb: I/O error: cannot create the directory '" + (file / "results").string() +
                                  "': Not a directory");
  }
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace twb
