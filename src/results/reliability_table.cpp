#include "twb/results/reliability_table.h"

namespace twb {

namespace {

std::optional<double> as_number(const std::optional<long>& n) {
  return n ? std::optional<double>(double(*n)) : std::nullopt;
}

}  // namespace

ResultTable reliability_table(const std::vector<ReliabilityRow>& rows) {
  ResultTable t;
  const auto method = t.text("method"), load = t.number("load_N"), speed = t.number("speed_rad_s"),
             probability = t.number("probability"), beta = t.number("beta"), cov = t.number("cov"),
             low = t.number("low"), high = t.number("high"), samples = t.number("samples"),
             failures = t.number("failures"), unresolved = t.number("unresolved"), evaluations = t.count("evaluations"),
             converged = t.count("converged");
  for (const ReliabilityRow& r : rows) {
    t.put_text(method, r.method);
    t.put_number(load, r.load);
    t.put_number(speed, r.speed);
    t.put_number(probability, r.probability);
    t.put_number(beta, r.beta);
    t.put_number(cov, r.cov);
    t.put_number(low, r.low);
    t.put_number(high, r.high);
    t.put_number(samples, as_number(r.samples));
    t.put_number(failures, as_number(r.failures));
    t.put_number(unresolved, as_number(r.unresolved));
    t.put_count(evaluations, r.evaluations);
    t.put_count(converged, r.converged ? 1 : 0);
  }
  return t;
}

ResultTable design_point_table(const std::vector<DesignPointRow>& rows) {
  ResultTable t;
  const auto method = t.text("method"), load = t.number("load_N"), probability = t.number("probability"),
             parameter = t.text("parameter"), unit = t.text("parameter_unit"), distribution = t.text("distribution"),
             mean = t.number("mean"), sd = t.number("sd"), lower = t.number("lower"), upper = t.number("upper"),
             design_value = t.number("design_value"), u = t.number("u"), alpha = t.number("alpha"),
             importance = t.number("importance"), derivative = t.number("derivative");
  for (const DesignPointRow& r : rows) {
    t.put_text(method, r.method);
    t.put_number(load, r.load);
    t.put_number(probability, r.probability);
    t.put_text(parameter, r.parameter);
    t.put_text(unit, r.parameter_unit);
    t.put_text(distribution, r.distribution);
    t.put_number(mean, r.mean);
    t.put_number(sd, r.sd);
    t.put_number(lower, r.lower);
    t.put_number(upper, r.upper);
    t.put_number(design_value, r.design_value);
    t.put_number(u, r.u);
    t.put_number(alpha, r.alpha);
    t.put_number(importance, r.importance);
    t.put_number(derivative, r.derivative);
  }
  return t;
}

}  // namespace twb
