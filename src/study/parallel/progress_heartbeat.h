// A study's progress lines, and a line of its own where the study has been quiet for a
// while: a cold start that fails, an arclength round a fold that is not there, a
// transient near a fold can each work for tens of seconds between two lines, and a
// user watching a terminal cannot tell work from a hang (issue: "no study prints
// nothing for more than a few seconds").
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "twb/study/study_outcome.h"

namespace twb {

class ProgressHeartbeat {
 public:
  // Every line given to report() goes to `sink`; where none came for `quiet`, the
  // heartbeat writes "still at work, N s after: <the last line>" (and again each
  // `quiet` on). `sink` is called from this object's thread too, never at once.
  ProgressHeartbeat(ProgressReport sink, std::chrono::milliseconds quiet);
  ~ProgressHeartbeat();
  ProgressHeartbeat(const ProgressHeartbeat&) = delete;
  ProgressHeartbeat& operator=(const ProgressHeartbeat&) = delete;

  // The report a study is given; valid as long as this object.
  ProgressReport report();

 private:
  void beat();

  ProgressReport sink_;
  std::chrono::milliseconds quiet_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::string last_;
  std::chrono::steady_clock::time_point last_at_, last_said_;
  std::thread thread_;
};

}  // namespace twb
