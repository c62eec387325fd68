#include "twb/results/calibration_table.h"

namespace twb {

ResultTable calibration_table(const std::vector<CalibrationRow>& rows) {
  ResultTable t;
  const auto parameter = t.text("parameter"), unit = t.text("parameter_unit"), start = t.number("start"),
             lower = t.number("lower"), upper = t.number("upper"), fitted = t.number("fitted"), sd = t.number("sd"),
             at_bound = t.text("at_bound");
  for (const CalibrationRow& r : rows) {
    t.put_text(parameter, r.parameter);
    t.put_text(unit, r.parameter_unit);
    t.put_number(start, r.start);
    t.put_number(lower, r.lower);
    t.put_number(upper, r.upper);
    t.put_number(fitted, r.fitted);
    t.put_number(sd, r.sd);
    t.put_text(at_bound, r.at_bound);
  }
  return t;
}

ResultTable correlation_table(const std::vector<CorrelationRow>& rows) {
  ResultTable t;
  const auto a = t.text("parameter_a"), b = t.text("parameter_b"), covariance = t.number("covariance"),
             correlation = t.number("correlation");
  for (const CorrelationRow& r : rows) {
    t.put_text(a, r.parameter_a);
    t.put_text(b, r.parameter_b);
    t.put_number(covariance, r.covariance);
    t.put_number(correlation, r.correlation);
  }
  return t;
}

ResultTable calibration_points_table(const std::vector<CalibrationPointRow>& rows) {
  ResultTable t;
  const auto point = t.count("point"), line = t.count("line"), load = t.number("load_N"),
             speed = t.number("speed_rad_s"), quantity = t.text("quantity"), measured = t.number("measured"),
             at_start = t.number("at_start"), fitted = t.number("fitted"), sd = t.number("sd"),
             residual = t.number("residual");
  for (const CalibrationPointRow& r : rows) {
    t.put_count(point, r.point);
    t.put_count(line, r.line);
    t.put_number(load, r.load);
    t.put_number(speed, r.speed);
    t.put_text(quantity, r.quantity);
    t.put_number(measured, r.measured);
    t.put_number(at_start, r.at_start);
    t.put_number(fitted, r.fitted);
    t.put_number(sd, r.sd);
    t.put_number(residual, r.residual);
  }
  return t;
}

}  // namespace twb
