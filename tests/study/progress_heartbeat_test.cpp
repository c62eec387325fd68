// A study's progress under a terminal (study/progress_heartbeat.h): every line passes
// through, and a quiet stretch longer than the heartbeat's own interval gets a line
// that says the study is still at work and after what. Intervals are milliseconds here;
// the waits are many intervals long, so that a loaded machine (sanitizers, two jobs at
// once) delays a beat without missing it.
#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "study/parallel/progress_heartbeat.h"

namespace twb {
namespace {

using namespace std::chrono_literals;

struct Lines {
  std::mutex mutex;
  std::vector<std::string> seen;
  ProgressReport sink() {
    return [this](const std::string& s) {
      const std::lock_guard lock(mutex);
      seen.push_back(s);
    };
  }
  std::vector<std::string> copy() {
    const std::lock_guard lock(mutex);
    return seen;
  }
};

TEST(ProgressHeartbeat, AQuietStretchSaysWhatIsStillAtWork) {
  Lines lines;
  {
    ProgressHeartbeat heartbeat(lines.sink(), 40ms);
    const ProgressReport report = heartbeat.report();
    report("  545 rad/s: 180.00 N on the cool branch");
    std::this_thread::sleep_for(400ms);
  }
  const std::vector<std::string> seen = lines.copy();
  ASSERT_GE(seen.size(), 2u);
  EXPECT_EQ(seen.front(), "  545 rad/s: 180.00 N on the cool branch");
  for (std::size_t k = 1; k < seen.size(); ++k) {
    EXPECT_NE(seen[k].find("still at work"), std::string::npos) << seen[k];
    EXPECT_NE(seen[k].find("after: 545 rad/s: 180.00 N on the cool branch"), std::string::npos) << seen[k];
  }
}

TEST(ProgressHeartbeat, ABusyStudyGetsNoBeat) {
  Lines lines;
  {
    ProgressHeartbeat heartbeat(lines.sink(), 2s);
    const ProgressReport report = heartbeat.report();
    for (int k = 0; k < 20; ++k) {
      report("line " + std::to_string(k));
      std::this_thread::sleep_for(5ms);
    }
  }
  const std::vector<std::string> seen = lines.copy();
  ASSERT_EQ(seen.size(), 20u);
  for (int k = 0; k < 20; ++k) EXPECT_EQ(seen[std::size_t(k)], "line " + std::to_string(k));
}

TEST(ProgressHeartbeat, ALongLineIsCutForTheTerminal) {
  Lines lines;
  {
    ProgressHeartbeat heartbeat(lines.sink(), 30ms);
    heartbeat.report()(std::string(300, 'x') + "\nsecond line");
    std::this_thread::sleep_for(300ms);
  }
  const std::vector<std::string> seen = lines.copy();
  ASSERT_GE(seen.size(), 2u);
  EXPECT_EQ(seen[1].find("second line"), std::string::npos) << seen[1];
  EXPECT_LT(seen[1].size(), 150u) << seen[1];
}

}  // namespace
}  // namespace twb
