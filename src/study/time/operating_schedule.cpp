#include "study/time/operating_schedule.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace twb {

OperatingSchedule::OperatingSchedule(std::vector<SchedulePoint> points) : points_(std::move(points)) {
  if (points_.size() < 2) throw std::invalid_argument("a schedule needs at least two points, its start and its end");
  for (std::size_t k = 1; k < points_.size(); ++k)
    if (!(points_[k].time > points_[k - 1].time))
      throw std::invalid_argument("a schedule's times must increase strictly from point to point");
}

std::size_t OperatingSchedule::segment_at(double t) const {
  const auto after = std::upper_bound(points_.begin(), points_.end(), t,
                                      [](double time, const SchedulePoint& p) { return time < p.time; });
  const std::size_t k = after == points_.begin() ? 0 : std::size_t(after - points_.begin()) - 1;
  return std::min(k, segments() - 1);
}

SchedulePoint OperatingSchedule::on_segment(std::size_t k, double t) const {
  const SchedulePoint& a = points_[k];
  const SchedulePoint& b = points_[k + 1];
  // Held outside the schedule; on the line within it.
  const double s = std::clamp((t - a.time) / (b.time - a.time), 0.0, 1.0);
  SchedulePoint p = s < 1.0 ? a : b;
  p.time = t;
  // (std::lerp: each point's own values exactly at its time.)
  p.load = std::lerp(a.load, b.load, s);
  p.speed = std::lerp(a.speed, b.speed, s);
  p.ambient = std::lerp(a.ambient, b.ambient, s);
  p.tilt = std::lerp(a.tilt, b.tilt, s);
  return p;
}

double OperatingSchedule::ambient_rate(std::size_t k) const {
  const SchedulePoint& a = points_[k];
  const SchedulePoint& b = points_[k + 1];
  return (b.ambient - a.ambient) / (b.time - a.time);
}

double OperatingSchedule::tilt_rate(std::size_t k) const {
  const SchedulePoint& a = points_[k];
  const SchedulePoint& b = points_[k + 1];
  return (b.tilt - a.tilt) / (b.time - a.time);
}

std::vector<SchedulePoint> OperatingSchedule::with_rests(std::vector<SchedulePoint> points) {
  std::vector<SchedulePoint> out;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (k > 0) {
      const SchedulePoint& a = points[k - 1];
      const SchedulePoint& b = points[k];
      if (a.load == 0.0 && b.load == 0.0 && ((a.speed > 0.0 && b.speed < 0.0) || (a.speed < 0.0 && b.speed > 0.0))) {
        const double s = a.speed / (a.speed - b.speed);
        SchedulePoint rest = a;
        rest.time = std::lerp(a.time, b.time, s);
        rest.speed = 0.0;
        rest.ambient = std::lerp(a.ambient, b.ambient, s);
        rest.tilt = std::lerp(a.tilt, b.tilt, s);
        // A zero a rounding away from an end is that end's: the washer rests there.
        if (rest.time <= a.time) out.back().speed = 0.0;
        else if (rest.time >= b.time) points[k].speed = 0.0;
        else out.push_back(rest);
      }
    }
    out.push_back(std::move(points[k]));
  }
  return out;
}

void OperatingSchedule::apply(BearingModel& model, const SchedulePoint& p) {
  model.set_load(p.load);
  model.set_speed(p.speed);
  if (model.curve_parameter(CurveParameter::ambient_temperature) != p.ambient)
    model.set_curve_parameter(CurveParameter::ambient_temperature, p.ambient);
  if (model.curve_parameter(CurveParameter::gear_tilt) != p.tilt)
    model.set_curve_parameter(CurveParameter::gear_tilt, p.tilt);
}

}  // namespace twb
