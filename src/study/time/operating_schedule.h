// A duty cycle's operating point in time (docs/physics.md section 19): the schedule's
// points joined by straight lines, held at the first point's values before it and the
// last's after it, and set on the bearing at any time.
#pragma once

#include <cstddef>
#include <vector>

#include "model/bearing_model.h"
#include "twb/scene/scene.h"

namespace twb {

class OperatingSchedule {
 public:
  // `points`: at least two, times strictly increasing (the scene reader's checks); else
  // std::invalid_argument.
  explicit OperatingSchedule(std::vector<SchedulePoint> points);

  const std::vector<SchedulePoint>& points() const { return points_; }
  std::size_t segments() const { return points_.size() - 1; }
  double start() const { return points_.front().time; }
  double end() const { return points_.back().time; }
  // The segment a time lies in: the last one starting at or before it (the first before
  // the schedule, the last after it).
  std::size_t segment_at(double t) const;
  // The operating point at t on segment k's line (time, load, speed, ambient, tilt); the
  // lines meet at the points, so any segment holding t gives the same values there.
  SchedulePoint on_segment(std::size_t k, double t) const;
  SchedulePoint at(double t) const { return on_segment(segment_at(t), t); }
  // The ambient's rate on segment k (K/s): where a march restarts, the rates jump.
  double ambient_rate(std::size_t k) const;
  // The gear tilt's rate on segment k (rad/s), which the film's squeeze reads.
  double tilt_rate(std::size_t k) const;

  // Sets the point's load, speed, ambient and gear tilt on the bearing.
  static void apply(BearingModel& model, const SchedulePoint& p);

  // Whether the washer is unloaded at rest at p: load and speed both zero (docs/physics.md
  // section 19, the rigid body held).
  static bool unloaded_at_rest(const SchedulePoint& p) { return p.load == 0.0 && p.speed == 0.0; }
  // The points with one more where a segment unloaded at both ends turns its speed back:
  // the washer is unloaded at rest there, at a point of its own (the march holds the rigid
  // body from there, and gives the balances back after it, at points).
  static std::vector<SchedulePoint> with_rests(std::vector<SchedulePoint> points);

 private:
  std::vector<SchedulePoint> points_;
};

}  // namespace twb
