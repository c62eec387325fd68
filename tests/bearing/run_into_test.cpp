// Bearing::run_into (twb/bearing.h), the one way twb run, twb merge and twb.run(out=DIR)
// run a study into a results directory, on a coarse three-speed load sweep (three
// independent searches of a second or two): its files are those of the outcome
// run_study gives; a run told to stop writes only its journal, and resuming it ends
// with the uninterrupted run's numbers while running only the searches not journaled;
// a job array's slices taken in give the whole run's numbers; slices that are not this
// scene's are refused.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support/table1_scene.h"
#include "../support/test_files.h"
#include "study/parallel/search_journal.h"
#include "study/parallel/search_scheduler.h"
#include "twb/bearing.h"

namespace twb {
namespace {

namespace fs = std::filesystem;

// 100 to 300 N in three steps at 136, 300 and 545 rad/s on the 5 × 24 mesh.
Scene coarse_sweep() {
  Scene s = testing::table1_scene(true, true, true, true, 545.0, 100.0);
  testing::use_coarse_mesh(s);
  LoadSweepSettings sweep;
  sweep.grid.loads = {100.0, 300.0};
  sweep.grid.load_steps = 3;
  sweep.grid.speeds = {136.0, 300.0, 545.0};
  s.study.settings = sweep;
  return s;
}

fs::path fresh_dir(const std::string& name) { return testing::fresh_directory("run_into", name); }

using testing::file_text;

// The numbers of two outcomes the same to the last bit: each search's distress row and
// every state's load, speed and temperatures (their measured times aside).
void expect_same_numbers(const StudyOutcome& a, const StudyOutcome& b) {
  ASSERT_EQ(a.distress.size(), b.distress.size());
  for (std::size_t i = 0; i < a.distress.size(); ++i) {
    EXPECT_EQ(a.distress[i].speed, b.distress[i].speed);
    EXPECT_EQ(a.distress[i].distress_load, b.distress[i].distress_load) << "search " << i;
    EXPECT_EQ(a.distress[i].method, b.distress[i].method) << "search " << i;
  }
  ASSERT_EQ(a.states.size(), b.states.size());
  for (std::size_t i = 0; i < a.states.size(); ++i) {
    EXPECT_EQ(a.states[i].state.load, b.states[i].state.load) << "state " << i;
    EXPECT_EQ(a.states[i].state.speed, b.states[i].state.speed) << "state " << i;
    EXPECT_EQ(a.states[i].state.washer_max_temperature, b.states[i].state.washer_max_temperature) << "state " << i;
    EXPECT_EQ(a.states[i].state.torque, b.states[i].state.torque) << "state " << i;
  }
}

// How many of a run's progress lines say a search was read from the journal.
struct ProgressLines {
  std::vector<std::string> lines;
  ProgressReport report() {
    return [this](const std::string& line) { lines.push_back(line); };
  }
  int containing(const std::string& text) const {
    int n = 0;
    for (const std::string& l : lines) n += l.find(text) != std::string::npos;
    return n;
  }
};

class RunInto : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    Bearing bearing(coarse_sweep());
    whole_ = new StudyOutcome(bearing.run_study());
  }
  static void TearDownTestSuite() { delete whole_; }
  static const StudyOutcome& whole() { return *whole_; }

 private:
  static StudyOutcome* whole_;
};
StudyOutcome* RunInto::whole_ = nullptr;

TEST_F(RunInto, WritesTheFilesOfTheOutcomeRunStudyGives) {
  ASSERT_EQ(whole().distress.size(), 3u);
  ASSERT_FALSE(whole().solver_failed) << whole().message;
  const fs::path dir = fresh_dir("whole");
  Bearing bearing(coarse_sweep());
  const StudyOutcome out = bearing.run_into(ResultsDirectory(dir), ResultsRun{});
  expect_same_numbers(out, whole());
  EXPECT_TRUE(fs::exists(dir / "states.csv"));
  bool compared = false;
  for (const NamedTable& t : study_tables(whole(), StudyType::load_sweep)) {
    if (t.name != "distress") continue;
    EXPECT_EQ(file_text(dir / "distress.csv"), t.table.csv(10));
    compared = true;
  }
  EXPECT_TRUE(compared) << "a load sweep writes distress.csv";
  EXPECT_TRUE(fs::exists(dir / "run.json"));
  EXPECT_FALSE(fs::exists(dir / ".twb-journal")) << "a complete run leaves nothing to resume";
  fs::remove_all(dir);
}

// Stopped once the first search is done (one thread: the others have not begun), the
// run writes no table and no run.json, and its journal holds that search; resumed, it
// reads that search and runs the two others, and ends with the whole run's numbers.
TEST_F(RunInto, AStoppedRunResumesToTheUninterruptedNumbers) {
  const fs::path dir = fresh_dir("stopped");
  {
    std::atomic<bool> stop{false};
    Bearing bearing(coarse_sweep());
    const ProgressReport stop_after_first = [&](const std::string& line) {
      if (line.rfind("[1/3] done", 0) == 0) stop.store(true);
    };
    const StudyOutcome out = bearing.run_into(ResultsDirectory(dir), ResultsRun{}, stop_after_first,
                                              RunOptions{.threads = 1, .stop = &stop});
    EXPECT_TRUE(out.stopped);
    EXPECT_FALSE(fs::exists(dir / "run.json"));
    EXPECT_FALSE(fs::exists(dir / "distress.csv"));
    EXPECT_EQ(SearchJournal::entries_in(dir), std::vector<std::size_t>{0});
  }
  Bearing bearing(coarse_sweep());
  ProgressLines progress;
  const StudyOutcome out = bearing.run_into(ResultsDirectory(dir), ResultsRun{.resume = true}, progress.report());
  EXPECT_FALSE(out.stopped);
  EXPECT_EQ(progress.containing("from the journal"), 1);
  EXPECT_EQ(progress.containing("] done:"), 3) << "each search is taken once, the journaled one included";
  expect_same_numbers(out, whole());
  EXPECT_TRUE(fs::exists(dir / "run.json"));
  EXPECT_FALSE(fs::exists(dir / ".twb-journal"));
  fs::remove_all(dir);
}

// Without resume the journal of an earlier run is discarded: every search runs.
TEST_F(RunInto, WithoutResumeAnEarlierJournalIsNotRead) {
  const fs::path dir = fresh_dir("afresh");
  {
    Bearing bearing(coarse_sweep());
    SliceScheduler first(1, 3);
    bearing.run_into(ResultsDirectory(dir), ResultsRun{}, {}, RunOptions{.scheduler = &first});
    ASSERT_EQ(SearchJournal::entries_in(dir), std::vector<std::size_t>{0});
  }
  Bearing bearing(coarse_sweep());
  ProgressLines progress;
  bearing.run_into(ResultsDirectory(dir), ResultsRun{}, progress.report());
  EXPECT_EQ(progress.containing("from the journal"), 0);
  fs::remove_all(dir);
}

// A worn washer (--continue-from) is named in its scene's text by a comment only, which
// the journal's comparison leaves out (it names the file as typed): the journal keeps the
// washer's depths beside the scene, and a resume with another washer, or none, is
// refused rather than mixing the two washers' searches.
TEST(SearchJournal, AWornWashersRunResumesOnlyWithThatWasher) {
  const fs::path dir = fresh_dir("worn");
  const std::string scene = "study:\n  type: load_sweep\n";
  WornWasher worn{.time = 3600.0, .film = 1, .inner_radius = 0.01, .outer_radius = 0.02, .radial_nodes = 2,
                  .circumferential_nodes = 2, .rest = {0.0, 1e-7, 2e-7, 3e-7}, .turn = {1e-8, 2e-8},
                  .rest_rq = {}, .turn_rq = {}, .source = {}};
  const std::string identity = SearchJournal::worn_identity(worn);
  const SearchJournal written(dir, scene, false, identity);
  EXPECT_NO_THROW(SearchJournal(dir, scene, true, identity));
  auto refusal = [&](const std::string& other) {
    try {
      const SearchJournal resumed(dir, scene, true, other);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("resumed");
  };
  EXPECT_NE(refusal("").find("written for a worn washer (--continue-from) and this run is of a new washer"),
            std::string::npos)
      << refusal("");
  worn.rest[1] *= 1.0 + 1e-15;
  EXPECT_NE(refusal(SearchJournal::worn_identity(worn)).find("this run is of another worn washer"), std::string::npos);
  const SearchJournal fresh(dir, scene, false);  // a new washer's run
  EXPECT_NE(refusal(identity).find("written for a new washer and this run is of a worn washer"), std::string::npos);
  fs::remove_all(dir);
}

// A job array's two slices, each journaling its share and writing no table, taken in
// by a third run (twb merge) that runs nothing itself.
TEST_F(RunInto, SlicesTakenInGiveTheWholeRunsNumbers) {
  const fs::path a = fresh_dir("slice1"), b = fresh_dir("slice2"), merged = fresh_dir("merged");
  for (int k : {1, 2}) {
    Bearing bearing(coarse_sweep());
    SliceScheduler slice(k, 2);
    const StudyOutcome out =
        bearing.run_into(ResultsDirectory(k == 1 ? a : b), ResultsRun{}, {}, RunOptions{.scheduler = &slice});
    EXPECT_FALSE(fs::exists((k == 1 ? a : b) / "run.json")) << "a slice's result is its journal";
  }
  EXPECT_EQ(SearchJournal::entries_in(a).size() + SearchJournal::entries_in(b).size(), 3u);
  Bearing bearing(coarse_sweep());
  ProgressLines progress;
  const StudyOutcome out =
      bearing.run_into(ResultsDirectory(merged), ResultsRun{.slices = {a.string(), b.string()}}, progress.report());
  EXPECT_EQ(progress.containing("from the journal"), 3);
  expect_same_numbers(out, whole());
  EXPECT_TRUE(fs::exists(merged / "run.json"));
  for (const fs::path& d : {a, b, merged}) fs::remove_all(d);
}

// A directory without a journal, and a slice of a run of another scene (another load
// grid), are refused before anything runs, each by its directory's name.
TEST_F(RunInto, SlicesNotOfThisScenesRunAreRefused) {
  const fs::path empty = fresh_dir("nojournal"), other = fresh_dir("other"), merged = fresh_dir("refused");
  fs::create_directories(empty);
  {
    Scene s = coarse_sweep();
    std::get<LoadSweepSettings>(s.study.settings).grid.load_steps = 2;
    Bearing bearing(s);
    SliceScheduler slice(1, 2);
    bearing.run_into(ResultsDirectory(other), ResultsRun{}, {}, RunOptions{.scheduler = &slice});
  }
  Bearing bearing(coarse_sweep());
  try {
    bearing.run_into(ResultsDirectory(merged), ResultsRun{.slices = {empty.string()}});
    ADD_FAILURE() << "a directory without a journal was taken as a slice";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'" + empty.string() + "' holds no journaled searches"), std::string::npos)
        << e.what();
  }
  try {
    bearing.run_into(ResultsDirectory(merged), ResultsRun{.slices = {other.string()}});
    ADD_FAILURE() << "another scene's slice was taken in";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'" + other.string() + "' belongs to another scene"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(merged / "run.json"));
  for (const fs::path& d : {empty, other, merged}) fs::remove_all(d);
}

}  // namespace
}  // namespace twb
