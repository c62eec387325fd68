// The results directory's promises (twb/results/results_directory.h, interruption.h),
// checked on the real binary: an earlier run's files are gone before a run writes, a
// second run into a locked directory is refused, an unusable directory is an I/O error
// before any work, and SIGTERM ends a run with a message and no partial run.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "../support/test_files.h"

namespace twb {
namespace {

namespace fs = std::filesystem;

struct Finished {
  int status = -1;
  std::string err;
};

fs::path fresh_dir(const std::string& name) { return testing::fresh_directory("results_directory_test", name); }

using testing::file_text;

// twb run on the paper's scene with `extra` arguments, stderr kept; the exit status.
Finished run_twb(const fs::path& out, const std::string& extra) {
  const fs::path err = fs::temp_directory_path() / ("twb_results_directory_test_" + std::to_string(getpid()) + ".stderr");
  const std::string command = std::string("'") + TWB_BINARY + "' run '" + TWB_SOURCE_DIR +
                              "/configs/jackson_green_2006.yaml' -q --out '" + out.string() + "' " + extra + " > /dev/null 2> '" +
                              err.string() + "'";
  const int status = std::system(command.c_str());
  Finished f{WIFEXITED(status) ? WEXITSTATUS(status) : -1, file_text(err)};
  fs::remove(err);
  return f;
}

TEST(ResultsDirectory, AnEarlierRunsFilesAreGoneBeforeTheRunWrites) {
  const fs::path dir = fresh_dir("stale");
  fs::create_directories(dir / "figures");
  std::ofstream(dir / "distress.csv") << "an earlier sweep's distress\n";
  std::ofstream(dir / "cycle_events.csv") << "an earlier duty cycle's events\n";
  std::ofstream(dir / "figures" / "fig06_temperature.png") << "an earlier figure";
  std::ofstream(dir / "notes.txt") << "the user's own file";
  const Finished f = run_twb(dir, "--set 'study={type: point}'");
  ASSERT_EQ(f.status, 0) << f.err;
  EXPECT_FALSE(fs::exists(dir / "distress.csv")) << "a point study writes no distress table";
  EXPECT_FALSE(fs::exists(dir / "cycle_events.csv")) << "nor a duty cycle's events";
  EXPECT_FALSE(fs::exists(dir / "figures" / "fig06_temperature.png"));
  EXPECT_TRUE(fs::exists(dir / "notes.txt")) << "files twb does not write are left alone";
  EXPECT_TRUE(fs::exists(dir / "states.csv") && fs::exists(dir / "run.json"));
  fs::remove_all(dir);
}

TEST(ResultsDirectory, ASecondRunIntoALockedDirectoryIsRefused) {
  const fs::path dir = fresh_dir("locked");
  fs::create_directories(dir);
  // This process plays the first run: it holds the directory's lock.
  const int fd = open((dir / ".twb.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(flock(fd, LOCK_EX | LOCK_NB), 0);
  std::ofstream(dir / "states.csv") << "the first run's states\n";
  const Finished f = run_twb(dir, "--set 'study={type: point}'");
  EXPECT_EQ(f.status, 2);
  EXPECT_NE(f.err.find("another twb run"), std::string::npos) << f.err;
  EXPECT_EQ(file_text(dir / "states.csv"), "the first run's states\n") << "the first run's files were touched";
  close(fd);  // the first run ends: the directory is free again
  EXPECT_EQ(run_twb(dir, "--set 'study={type: point}'").status, 0);
  fs::remove_all(dir);
}

// A directory under a regular file cannot be made, for root too: the I/O error's exit
// status 5 and words, which name the directory and the system's reason, not a bug.
TEST(ResultsDirectory, AnUnusableDirectoryIsAnIoErrorBeforeAnyWork) {
  const fs::path file = fresh_dir("file");
  std::ofstream(file) << "a file, not a directory";
  const Finished f = run_twb(file / "results", "");
  EXPECT_EQ(f.status, 5);
  EXPECT_NE(f.err.find("twb: I/O error: cannot make the results directory '" + (file / "results").string() +
                       "': Not a directory"),
            std::string::npos)
      << f.err;
  EXPECT_EQ(f.err.find("report"), std::string::npos) << f.err;
  // The default study takes seconds; refusing the directory takes none of them.
  EXPECT_EQ(f.err.find("unknowns"), std::string::npos) << "the model was built before the check: " << f.err;
  fs::remove(file);
}

TEST(ResultsDirectory, SigtermEndsARunWithAMessageAndNoPartialRun) {
  const fs::path dir = fresh_dir("sigterm");
  const fs::path err = dir.string() + ".stderr";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(e, STDERR_FILENO);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    const std::string scene = std::string(TWB_SOURCE_DIR) + "/configs/studies/distress_map.yaml";
    execl(TWB_BINARY, TWB_BINARY, "run", scene.c_str(), "--out", dir.c_str(), "--threads", "1", nullptr);
    _exit(127);
  }
  // The map runs for seconds: stop it while it searches (its directory then exists).
  for (int k = 0; k < 200 && !fs::exists(dir / ".twb.lock"); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(kill(child, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  const std::string message = file_text(err);
  EXPECT_NE(message.find("terminated (SIGTERM)"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir / "run.json")) << "an interrupted run must not look complete";
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "a half-written file: " << e.path();
  fs::remove_all(dir);
  fs::remove(err);
}

}  // namespace
}  // namespace twb
