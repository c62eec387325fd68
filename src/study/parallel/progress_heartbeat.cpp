#include "study/parallel/progress_heartbeat.h"

#include <fmt/format.h>

namespace twb {

namespace {
// The last line as the heartbeat repeats it: its first line, short enough for a terminal.
std::string gist(const std::string& line) {
  constexpr std::size_t kWidth = 100;
  std::string s = line.substr(0, line.find('\n'));
  const std::size_t text = s.find_first_not_of(' ');
  s.erase(0, text == std::string::npos ? s.size() : text);
  return s.size() > kWidth ? s.substr(0, kWidth - 3) + "..." : s;
}
}  // namespace

ProgressHeartbeat::ProgressHeartbeat(ProgressReport sink, std::chrono::milliseconds quiet)
    : sink_(std::move(sink)),
      quiet_(quiet),
      last_at_(std::chrono::steady_clock::now()),
      last_said_(last_at_),
      thread_([this] { beat(); }) {}

ProgressHeartbeat::~ProgressHeartbeat() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

ProgressReport ProgressHeartbeat::report() {
  return [this](const std::string& line) {
    const std::lock_guard lock(mutex_);
    if (sink_) sink_(line);
    last_ = line;
    last_at_ = last_said_ = std::chrono::steady_clock::now();
  };
}

void ProgressHeartbeat::beat() {
  std::unique_lock lock(mutex_);
  while (!stop_) {
    const auto due = last_said_ + quiet_;
    if (wake_.wait_until(lock, due, [&] { return stop_; })) break;
    const auto now = std::chrono::steady_clock::now();
    if (now < last_said_ + quiet_) continue;  // a line came meanwhile
    const double seconds = std::chrono::duration<double>(now - last_at_).count();
    if (sink_)
      sink_(last_.empty() ? fmt::format("  still at work, {:.0f} s in", seconds)
                          : fmt::format("  still at work, {:.0f} s after: {}", seconds, gist(last_)));
    last_said_ = now;
  }
}

}  // namespace twb
