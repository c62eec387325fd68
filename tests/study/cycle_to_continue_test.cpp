// A duty cycle asked to go on from a results directory (twb run --continue-from DIR,
// twb.run(continue_from=DIR)): both read and check it through cycle_to_continue, so both
// refuse the same things in the same words.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "twb/results/cycle_state.h"
#include "twb/scene/scene_loader.h"
#include "twb/study/study_outcome.h"

namespace twb {
namespace {

namespace fs = std::filesystem;

Scene scene_of(const std::string& study) {
  return load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
                    {"mesh.radial_nodes=5", "mesh.circumferential_nodes=24", "study=" + study});
}

// The message of the std::invalid_argument `read` throws; empty where it throws none.
template <class Read>
std::string refusal(Read read) {
  try {
    read();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

class CycleToContinue : public ::testing::Test {
 protected:
  void SetUp() override {
    from = fs::path(::testing::TempDir()) / "twb_cycle_to_continue_from";
    other = fs::path(::testing::TempDir()) / "twb_cycle_to_continue_other";
    fs::remove_all(from);
    fs::remove_all(other);
    fs::create_directories(from);
    fs::create_directories(other);
  }
  void TearDown() override {
    fs::remove_all(from);
    fs::remove_all(other);
  }
  void write_end(const CycleState& end) const { std::ofstream(from / "cycle_end_state.json") << cycle_state_json(end); }

  fs::path from, other;
  const Scene cycle = scene_of("{type: duty_cycle, schedule: [{t: 0 s, load: 100 N}, {t: 5 s}]}");
};

// The end state written into a directory comes back as written (cycle_state_json writes
// every double to 17 digits, so exactly).
TEST_F(CycleToContinue, ReadsTheEndStateADirectoryHolds) {
  CycleState end;
  end.time = 5.0;
  end.load = 150.0;
  end.speed = 600.0;
  end.ambient = 303.15;
  end.unknowns = {0.1, 1.0 / 3.0, -2.5e-7};
  end.bearing = "the bearing";
  write_end(end);
  const CycleState back = cycle_to_continue(cycle.study, from.string(), other.string(), "--continue-from");
  EXPECT_EQ(back.time, end.time);
  EXPECT_EQ(back.load, end.load);
  EXPECT_EQ(back.unknowns, end.unknowns);
  EXPECT_EQ(back.bearing, end.bearing);
  // No results written (a Python run with out=False): nothing to compare with.
  EXPECT_EQ(cycle_to_continue(cycle.study, from.string(), "", "continue_from").unknowns, end.unknowns);
}

TEST_F(CycleToContinue, RefusesAnotherStudyADirectoryWithoutAnEndAndItsOwnDirectoryAsOut) {
  write_end(CycleState{});
  // The study's type first: a point study cannot go on, whatever the directory holds.
  const Scene point = scene_of("{type: point}");
  EXPECT_NE(refusal([&] { cycle_to_continue(point.study, (other / "none").string(), "", "--continue-from"); })
                .find("this scene's study is a point"),
            std::string::npos);
  EXPECT_NE(refusal([&] { cycle_to_continue(cycle.study, other.string(), "", "continue_from"); }).find("cannot read it"),
            std::string::npos);
  // The same directory however it is written: the new end state would replace the old.
  const std::string same = (from / ".").string();
  const std::string message = refusal([&] { cycle_to_continue(cycle.study, from.string(), same, "--continue-from"); });
  EXPECT_NE(message.find("--continue-from"), std::string::npos) << message;
  EXPECT_NE(message.find("would replace the one it starts from"), std::string::npos) << message;
}

}  // namespace
}  // namespace twb
