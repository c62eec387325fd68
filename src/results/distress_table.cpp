#include "twb/results/distress_table.h"

#include <algorithm>

#include <fmt/format.h>

#include "result_cells.h"

namespace twb {

std::string criterion_name(const FailureCriterion& criterion) {
  return criterion.distress ? "distress" : std::string(limit_name(criterion.limit));
}

std::string convergence_phrase(const LoadConvergence& c) {
  if (c.meshes.empty()) return {};
  return fmt::format("on {}{}", c.meshes, c.order ? fmt::format(", observed order {:.2f}", *c.order) : std::string());
}

std::string criterion_column(LimitKind kind, const char* suffix) {
  std::string name(limit_name(kind));
  std::replace(name.begin(), name.end(), ':', '_');
  return "W_" + name + suffix + "_N";
}

ResultTable distress_table(const std::vector<DistressRow>& rows, const std::vector<std::string>& parameter_columns,
                           bool sliding_column) {
  ResultTable t;
  const auto speed = t.number("speed_rad_s");
  const cells::RunColumns run(t, parameter_columns, sliding_column);
  const auto w_fail = t.number("W_fail_N");
  const auto criterion = t.text("criterion");
  const auto fail_extrapolated = t.number("W_fail_extrapolated_N"), fail_error = t.number("W_fail_error_N");
  const cells::ConvergenceColumns fail_convergence(t, "W_fail", true);
  const auto w_d = t.number("W_d_N"), low = t.number("bracket_low_N"), high = t.number("bracket_high_N"),
             fold = t.number("fold_N"), fine = t.number("W_d_fine_N"), extrapolated = t.number("W_d_extrapolated_N"),
             error = t.number("W_d_error_N");
  const cells::ConvergenceColumns fold_convergence(t, "W_d", false);
  std::vector<ResultTable::Column> criteria, criterion_errors, criterion_extrapolated;
  for (LimitKind kind : kFailureCriteria) criteria.push_back(t.number(criterion_column(kind, "")));
  for (LimitKind kind : kFailureCriteria) criterion_errors.push_back(t.number(criterion_column(kind, "_error")));
  for (LimitKind kind : kFailureCriteria)
    criterion_extrapolated.push_back(t.number(criterion_column(kind, "_extrapolated")));
  const auto failure = t.text("failure"), method = t.text("method");
  for (const DistressRow& r : rows) {
    t.put_number(speed, r.speed);
    run.put(t, r.parameters, r.sliding);
    t.put_number(w_fail, r.failure_load);
    t.put_text(criterion, r.criterion ? criterion_name(*r.criterion) : std::string());
    t.put_number(fail_extrapolated, r.failure_extrapolated);
    t.put_number(fail_error, r.failure_error);
    fail_convergence.put(t, r.failure_convergence);
    t.put_number(w_d, r.distress_load);
    t.put_number(low, r.bracket_low);
    t.put_number(high, r.bracket_high);
    t.put_number(fold, r.fold_load);
    t.put_number(fine, r.fine_fold_load);
    t.put_number(extrapolated, r.extrapolated_load);
    t.put_number(error, r.discretization_error);
    fold_convergence.put(t, r.fold_convergence);
    for (std::size_t k = 0; k < criteria.size(); ++k) t.put_number(criteria[k], r.criterion_loads[k]);
    for (std::size_t k = 0; k < criteria.size(); ++k) t.put_number(criterion_errors[k], r.criterion_errors[k]);
    for (std::size_t k = 0; k < criteria.size(); ++k)
      t.put_number(criterion_extrapolated[k], r.criterion_extrapolated[k]);
    t.put_text(failure, r.failure);
    t.put_text(method, r.method);
  }
  return t;
}

std::optional<double> criterion_load(const DistressRow& row, LimitKind kind) {
  const std::optional<std::size_t> c = criterion_index(kind);
  return c ? row.criterion_loads[*c] : std::nullopt;
}

std::string distress_csv(const std::vector<DistressRow>& rows, const std::vector<std::string>& parameter_columns,
                         bool sliding_column) {
  return distress_table(rows, parameter_columns, sliding_column).csv();
}

}  // namespace twb
