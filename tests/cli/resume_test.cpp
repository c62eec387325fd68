// After kill -9, `twb run --resume` finishes the study and ends with the files an
// uninterrupted run writes: byte for byte but for the measured times (the states'
// wall_ms column and run.json's *_ms), which differ between any two runs. A real run
// of a four-speed distress map is killed at seeded random moments (before, between and
// inside its searches) and resumed.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../support/test_files.h"

namespace twb {
namespace {

namespace fs = std::filesystem;

using testing::file_text;

// The map on the paper's mesh, no error bars, one thread: four searches of about half a
// second each.
std::vector<std::string> map_arguments(const fs::path& out) {
  return {TWB_BINARY, "run", std::string(TWB_SOURCE_DIR) + "/configs/studies/distress_map.yaml", "--out", out.string(),
          "--threads", "1", "-q", "--set", "study.error_estimate=none"};
}

pid_t start(std::vector<std::string> args) {
  const pid_t child = fork();
  if (child == 0) {
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return child;
}

int finish(pid_t child) {
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

// The CSV with its wall_ms column blanked.
std::string without_wall_times(const std::string& csv) {
  std::stringstream in(csv);
  std::string line, out;
  int column = -1;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (column < 0)
      for (std::size_t k = 0; k < cells.size(); ++k)
        if (cells[k] == "wall_ms") column = int(k);
    if (column >= 0 && std::size_t(column) < cells.size()) cells[std::size_t(column)] = "-";
    for (std::size_t k = 0; k < cells.size(); ++k) out += (k ? "," : "") + cells[k];
    out += "\n";
  }
  return out;
}

std::string without_times(const std::string& json) {
  static const std::regex times(R"re("([a-z_]+_ms)": [0-9.e+-]+)re");
  return std::regex_replace(json, times, "\"$1\": -");
}

bool has_journaled_search(const fs::path& journal) {
  std::error_code error;
  for (fs::directory_iterator it(journal, error), end; !error && it != end; it.increment(error))
    if (it->path().filename().string().rfind("search-", 0) == 0) return true;
  return false;
}

TEST(Resume, AKilledMapFinishesAsAnUninterruptedOne) {
  const fs::path base = fs::temp_directory_path() / ("twb_resume_test_" + std::to_string(getpid()));
  fs::remove_all(base);
  const fs::path whole = base / "whole";
  const auto started = std::chrono::steady_clock::now();
  ASSERT_EQ(finish(start(map_arguments(whole))), 0);
  const auto whole_time = std::chrono::steady_clock::now() - started;
  const std::string states = without_wall_times(file_text(whole / "states.csv"));
  const std::string distress = file_text(whole / "distress.csv");
  const std::string record = without_times(file_text(whole / "run.json"));
  ASSERT_FALSE(states.empty());

  int journaled = 0;  // searches a resume read instead of running them, over the kills
  // Moments as fractions of the uninterrupted run, so that a slower build (the
  // sanitizers' is ten times slower) is killed at the same stages.
  std::mt19937 seed(20261124);
  // (Up to 0.6: a machine whose load changes between the runs may run the killed one
  // faster than the measured one.)
  std::uniform_real_distribution<double> moment(0.05, 0.6);
  for (int kill = 0; kill < 3; ++kill) {
    const fs::path out = base / ("killed_" + std::to_string(kill));
    const pid_t child = start(map_arguments(out));
    if (kill == 0) {
      // The first kill waits for the first journaled search, so that at least one
      // resume reads a finished search rather than only running everything again.
      SCOPED_TRACE("killed once a search was journaled");
      const auto give_up = std::chrono::steady_clock::now() + 20 * whole_time;
      while (std::chrono::steady_clock::now() < give_up && !has_journaled_search(out / ".twb-journal"))
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    } else {
      const auto after = std::chrono::duration_cast<std::chrono::milliseconds>(moment(seed) * whole_time);
      SCOPED_TRACE("killed after " + std::to_string(after.count()) + " ms");
      std::this_thread::sleep_for(after);
    }
    ::kill(child, SIGKILL);
    finish(child);
    // A run that finished before its kill has nothing to resume; only the first kill,
    // which waits for the first of four searches, must find it unfinished.
    if (fs::exists(out / "run.json")) {
      EXPECT_NE(kill, 0) << "the run finished before its first search was journaled";
      continue;
    }
    if (fs::is_directory(out / ".twb-journal"))
      for (const fs::directory_entry& e : fs::directory_iterator(out / ".twb-journal"))
        journaled += e.path().filename().string().rfind("search-", 0) == 0;
    std::vector<std::string> resume = map_arguments(out);
    resume.push_back("--resume");
    ASSERT_EQ(finish(start(resume)), 0);
    EXPECT_EQ(without_wall_times(file_text(out / "states.csv")), states);
    EXPECT_EQ(file_text(out / "distress.csv"), distress);
    EXPECT_EQ(without_times(file_text(out / "run.json")), record);
    EXPECT_FALSE(fs::exists(out / ".twb-journal")) << "the journal outlived the finished run";
  }
  // The seeded moments stop the map between searches too: resumes must have had
  // finished searches to read, or this test would only show a rerun.
  EXPECT_GT(journaled, 0);
  fs::remove_all(base);
}

// A journal belongs to its scene: resuming with other values is refused, not mixed.
TEST(Resume, AnotherScenesJournalIsRefused) {
  const fs::path out = fs::temp_directory_path() / ("twb_resume_other_" + std::to_string(getpid()));
  fs::remove_all(out);
  const pid_t child = start(map_arguments(out));
  // Killed once its journal holds a search, not after a fixed time: a loaded machine or
  // the sanitizers' build may not have started one within it, and a journal-less
  // directory has nothing to refuse (the resume would simply run).
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (std::chrono::steady_clock::now() < give_up && !has_journaled_search(out / ".twb-journal"))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ::kill(child, SIGKILL);
  finish(child);
  ASSERT_TRUE(has_journaled_search(out / ".twb-journal")) << "no search journaled before the kill";
  ASSERT_FALSE(fs::exists(out / "run.json")) << "the run finished before its kill";
  std::vector<std::string> other = map_arguments(out);
  other.insert(other.end(), {"--set", "study.load_end=900 N", "--resume"});
  EXPECT_EQ(finish(start(other)), 2);
  fs::remove_all(out);
}

}  // namespace
}  // namespace twb
