// reliability.csv and design_point.csv (study type reliability, docs/physics.md section 17).
//
// reliability.csv, one row per answer:
//   method, load_N, speed_rad_s, probability, beta, cov, low, high, samples, failures,
//   unresolved, evaluations, converged
// method: form (the probability of failure at the operating load, Φ(−β)), monte_carlo
// (importance sampling round FORM's design point: the estimate, its coefficient of
// variation and 95 % interval low–high, with samples drawn, failures among them and
// unresolved ones left out), inverse_form (the load whose failure probability is the
// one asked for). evaluations: failure loads evaluated; converged: 1 or 0.
//
// design_point.csv, one row per (answer, input): where the inputs stand at its design point
//   method, load_N, probability, parameter, parameter_unit, distribution, mean, sd, lower,
//   upper, design_value, u, alpha, importance, derivative
// design_value the input there (SI), u its standard normal value, alpha its direction
// cosine (−∂g/∂u_i / |∇g|), importance α², derivative dW_fail/dx there (N per SI unit).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "twb/results/result_table.h"

namespace twb {

struct ReliabilityRow {
  std::string method;
  double load = 0.0;   // N
  double speed = 0.0;  // rad/s
  double probability = 0.0;
  std::optional<double> beta, cov, low, high;
  std::optional<long> samples, failures, unresolved;
  long evaluations = 0;
  bool converged = false;
};

struct DesignPointRow {
  std::string method;
  double load = 0.0;  // N
  double probability = 0.0;
  std::string parameter, parameter_unit, distribution;
  std::optional<double> mean, sd, lower, upper;
  double design_value = 0.0, u = 0.0, alpha = 0.0, importance = 0.0, derivative = 0.0;
};

ResultTable reliability_table(const std::vector<ReliabilityRow>& rows);
ResultTable design_point_table(const std::vector<DesignPointRow>& rows);

}  // namespace twb
