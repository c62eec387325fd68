// The fold curve's points as continuation accepts them (study type distress_curve), for
// the chains of refined folds that give their error bars on other threads: a chain waits
// for its own points, not for the whole curve, so the bars follow the curve while it is
// traced instead of after it.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "solver/fold_curve.h"

namespace twb {

class FoldCurveFeed {
 public:
  // A point and its fold's kind (+1 distress, −1 recovery).
  using Entry = std::pair<FoldCurvePoint, int>;

  void add(const FoldCurvePoint& point, int kind) {
    {
      const std::lock_guard<std::mutex> hold(lock_);
      points_.emplace_back(point, kind);
    }
    changed_.notify_all();
  }
  // The curve is traced, or has failed: no more points.
  void end() {
    {
      const std::lock_guard<std::mutex> hold(lock_);
      ended_ = true;
    }
    changed_.notify_all();
  }
  // Point k, once it is there; empty where the curve ended before it.
  std::optional<Entry> wait_for(std::size_t k) {
    std::unique_lock<std::mutex> hold(lock_);
    changed_.wait(hold, [&] { return ended_ || k < points_.size(); });
    if (k < points_.size()) return points_[k];
    return std::nullopt;
  }
  void wait_for_end() {
    std::unique_lock<std::mutex> hold(lock_);
    changed_.wait(hold, [&] { return ended_; });
  }

 private:
  std::mutex lock_;
  std::condition_variable changed_;
  std::vector<Entry> points_;
  bool ended_ = false;
};

// Ends the feed when the tracer's scope ends, however it ends: a chain never waits for a
// curve that threw.
class FeedEnds {
 public:
  explicit FeedEnds(FoldCurveFeed& feed) : feed_(feed) {}
  ~FeedEnds() { feed_.end(); }
  FeedEnds(const FeedEnds&) = delete;
  FeedEnds& operator=(const FeedEnds&) = delete;

 private:
  FoldCurveFeed& feed_;
};

}  // namespace twb
