#include "twb/results/cycle_table.h"

#include "result_cells.h"

namespace twb {

using cells::kelvin_offset;

ResultTable cycle_events_table(const std::vector<CycleEvent>& events) {
  ResultTable t;
  const auto time = t.number("t_s");
  const auto event = t.text("event"), criterion = t.text("criterion");
  const auto load = t.number("load_N"), speed = t.number("speed_rad_s"), ambient = t.number("ambient_C"),
             tilt = t.number("tilt_rad"), margin = t.number("margin"), failure_load = t.number("failure_load_N");
  const auto failure_criterion = t.text("failure_criterion");
  for (const CycleEvent& e : events) {
    t.put_number(time, e.time);
    t.put_text(event, e.event);
    t.put_text(criterion, e.criterion ? std::string(limit_name(*e.criterion)) : std::string());
    t.put_number(load, e.load);
    t.put_number(speed, e.speed);
    t.put_number(ambient, e.ambient - kelvin_offset);
    t.put_number(tilt, e.tilt);
    t.put_number(margin, e.margin);
    t.put_number(failure_load, e.failure_load);
    t.put_text(failure_criterion, e.failure_criterion ? criterion_name(*e.failure_criterion) : std::string());
  }
  return t;
}

}  // namespace twb
