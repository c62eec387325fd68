#include "study/uncertainty/sensitivity.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "results/result_cells.h"
#include "study/uncertainty/crossing_response.h"
#include "study/searches/distress_search.h"
#include "study/uncertainty/fold_response.h"
#include "study/searches/operating_point.h"
#include "study/parallel/parallel.h"
#include "study/study_support.h"
#include "twb/error_family.h"
#include "twb/results/distress_table.h"
#include "twb/scene/scene_inputs.h"

namespace twb {

namespace {

// What one input moves: each state quantity's derivative, W_d's and each crossing's, and
// why any of them is missing.
struct InputResponse {
  std::vector<double> state;
  std::optional<double> fold_load;
  std::vector<std::optional<double>> crossing_loads;
  double step = 0.0;
  std::string why;
};

// A derivative or nothing: a non-finite one (a neighbour's state past a table's range, a
// margin that vanished) is a reason, never a cell.
std::optional<double> finite(double d, const char* what, std::string& why) {
  if (std::isfinite(d)) return d;
  why += fmt::format("{}the derivative of {} is not finite", why.empty() ? "" : "; ", what);
  return std::nullopt;
}

}  // namespace

std::vector<StateQuantity> state_quantities(const BearingState& s) {
  return {{"torque_Nm", s.torque, false},
          {"f_eff", s.f_eff, false},
          {"T_mean_C", s.washer_mean_temperature, true},
          {"T_max_C", s.max_film_temperature, true},
          {"hmin_over_sigma", s.hmin_over_sigma, false},
          {"fluid_share", s.fluid_share, false}};
}

std::unique_ptr<SparseLu> jacobian_factors(const BearingModel& model, std::span<const double> u) {
  std::vector<double> f(u.size()), jac(std::size_t(model.pattern().nnz()));
  model.evaluate(u, f, jac);
  auto lu = std::make_unique<SparseLu>(model.pattern(), SparseLu::Ordering::minimum_degree);
  if (!lu->factor(jac)) return nullptr;
  return lu;
}

std::vector<double> state_derivatives(InputNeighbours& n, std::span<const double> u, double load, const SparseLu& lu,
                                      std::mutex& solve_lock) {
  std::vector<double> u_p = residual_derivative(n, u, load);
  {
    const std::lock_guard<std::mutex> hold(solve_lock);
    lu.solve(u_p);  // J⁻¹F_p: the state moves by −u_p per unit of p
  }
  return n.derivative([&](std::size_t k) {
    n.at[k]->set_load(n.load_at(k, load));
    std::vector<double> values;
    for (const StateQuantity& q : state_quantities(n.at[k]->describe(moved_state(u, u_p, n.stencil.offsets[k] * n.step))))
      values.push_back(q.value);
    return values;
  });
}

namespace {

// The inputs to differentiate: the study's, or every input the file writes that moves the
// bearing smoothly (stepwise_input), the others named in the summary.
std::vector<SceneInput> differentiated_inputs(const Scene& scene, StudyOutcome& out) {
  std::vector<SceneInput> inputs;
  if (const std::vector<std::string>& paths = std::get<SensitivitySettings>(scene.study.settings).parameters;
      !paths.empty()) {
    for (const std::string& path : paths) inputs.push_back(scene_input(scene, path));
    return inputs;
  }
  std::string left_out;
  for (const SceneInput& in : scene.inputs)
    if (stepwise_input(in.path).empty())
      inputs.push_back(in);
    else
      left_out += (left_out.empty() ? "" : ", ") + in.path;
  if (!left_out.empty())
    out.summary.push_back("sensitivity: left out, placed on the grid (their steps have no derivative): " + left_out);
  return inputs;
}

// With a load range: the failure search, its fold and every criterion's crossing, each
// settled to the solver's tolerance, and the rows W_fail's are (W_d_N or a crossing's
// column; empty without a failure).
struct SettledFailures {
  std::optional<SettledFold> fold;
  std::vector<SettledCrossing> crossings;
  std::string setting;
};

SettledFailures settled_failures(BearingModel& model, StudyOutcome& out, const ProgressReport& progress) {
  const FailureSearch& search = std::get<SensitivitySettings>(model.scene().study.settings).search;
  SettledFailures f;
  if (!(search.loads.end > 0.0)) return f;
  DistressSearchSettings settings = range_settings(search);
  settings.march_past_distress = false;
  DistressSearch found = search_distress(model, settings, progress);
  add_search_work(out.timings, found.counts);
  out.distress.push_back(found.row);
  std::string why;
  if (found.fold && found.fold_proven) {
    f.fold = settle_fold(model, *found.fold, why);
    if (!f.fold) out.summary.push_back("sensitivity: no derivatives of W_d: " + why);
  } else {
    out.summary.push_back("sensitivity: no proven fold in the load range, so no derivatives of W_d (" +
                          found.row.method + ")");
  }
  for (std::size_t c = 0; c < found.crossing_states.size(); ++c) {
    if (found.crossing_states[c].second.empty()) continue;
    std::optional<SettledCrossing> settled = settle_crossing(model, kFailureCriteria[c], found.crossing_states[c].first,
                                                             found.crossing_states[c].second, why);
    if (settled)
      f.crossings.push_back(std::move(*settled));
    else
      out.summary.push_back(fmt::format("sensitivity: no derivatives of {}: {}", criterion_column(kFailureCriteria[c]), why));
  }
  if (const std::optional<FailureCriterion>& c = found.row.criterion)
    f.setting = c->distress ? "W_d_N" : criterion_column(c->limit);
  return f;
}

// Each input on its own models; J's back-substitutions one at a time (KLU's solve writes
// into its factors' workspace).
std::vector<InputResponse> input_responses(BearingModel& model, const std::vector<SceneInput>& inputs,
                                           std::span<const double> u, double load, const SparseLu& factors,
                                           const SettledFailures& failures, int threads) {
  std::vector<InputResponse> response(inputs.size());
  std::mutex solve_lock;
  run_in_parallel(inputs.size(), threads, [&](std::size_t i) {
    InputResponse& r = response[i];
    try {
      InputNeighbours nb = input_neighbours(model, inputs[i]);
      r.step = nb.step;
      std::vector<double> state = state_derivatives(nb, u, load, factors, solve_lock);
      for (double d : state)
        if (!finite(d, "a state quantity", r.why)) return;
      r.state = std::move(state);
      // The failure loads do not depend on the operating load.
      if (inputs[i].path == kLoadInput) return;
      if (failures.fold) r.fold_load = finite(fold_load_derivative(nb, *failures.fold), "W_d", r.why);
      for (const SettledCrossing& c : failures.crossings)
        r.crossing_loads.push_back(
            finite(crossing_load_derivative(nb, c, solve_lock), criterion_column(c.kind).c_str(), r.why));
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      r.why += (r.why.empty() ? "" : "; ") + std::string(e.what());
    }
  });
  return response;
}

// The rows of sensitivity.csv: each state quantity's, each failure load's, then W_fail's
// (those of the criterion that sets it), and a summary line per input not (fully)
// differentiated. A temperature input's relative change is taken per the washer's mean
// rise above the ambient at the point (physics §16): in kelvin, the ambient's 350 K would
// make a derivative of a few newtons per kelvin the largest elasticity of all (none where
// the washer does not rise: the elasticity is then absent, as for p = 0).
void sensitivity_rows(const Scene& scene, const BearingState& at_point, const std::vector<SceneInput>& inputs,
                      const std::vector<InputResponse>& response, const SettledFailures& failures,
                      StudyOutcome& out) {
  const double ambient = scene.operating.ambient;
  const double rise = at_point.washer_mean_temperature - ambient;
  const auto input_scale = [&](const SceneInput& in) { return in.unit == "K" ? std::max(rise, 0.0) : in.value; };
  std::vector<SensitivityRow>& rows = out.own_part<SensitivityOutcome>().rows;
  auto row = [&](const std::string& name, double value, double reference, const SceneInput& in, double derivative,
                 double step) {
    SensitivityRow& r = rows.emplace_back();
    r.quantity = name;
    r.value = value;
    r.parameter = in.path;
    r.parameter_value = in.value;
    r.parameter_unit = in.unit;
    r.derivative = derivative == 0.0 ? 0.0 : derivative;  // no "-0" in the file
    if (const double scale = input_scale(in); reference != 0.0 && scale != 0.0)
      r.elasticity = r.derivative * scale / reference;
    r.step = step;
  };
  const std::vector<StateQuantity> quantities = state_quantities(at_point);
  for (std::size_t k = 0; k < quantities.size(); ++k)
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      if (response[i].state.empty()) continue;
      const StateQuantity& q = quantities[k];
      row(q.name, q.temperature ? q.value - cells::kelvin_offset : q.value, q.temperature ? q.value - ambient : q.value, inputs[i],
          response[i].state[k], response[i].step);
    }
  auto failure_rows = [&](const std::string& name, double w, auto derivative_of) {
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (const std::optional<double> d = derivative_of(response[i])) row(name, w, w, inputs[i], *d, response[i].step);
  };
  if (failures.fold) failure_rows("W_d_N", failures.fold->load, [](const InputResponse& r) { return r.fold_load; });
  for (std::size_t c = 0; c < failures.crossings.size(); ++c)
    failure_rows(criterion_column(failures.crossings[c].kind), failures.crossings[c].load, [c](const InputResponse& r) {
      return c < r.crossing_loads.size() ? r.crossing_loads[c] : std::nullopt;
    });
  for (std::size_t k = 0, end = rows.size(); k < end && !failures.setting.empty(); ++k)
    if (rows[k].quantity == failures.setting) {
      SensitivityRow copy = rows[k];
      copy.quantity = "W_fail_N";
      rows.push_back(std::move(copy));
    }
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (!response[i].why.empty())
      out.summary.push_back(fmt::format("sensitivity: {}: {}: {}", inputs[i].path,
                                        response[i].state.empty() ? "not differentiated" : "only partly differentiated",
                                        response[i].why));
}

// The inputs that matter most to the answer: W_fail's where there is one, else the torque's.
void rank_inputs(const std::vector<SceneInput>& inputs, double rise, StudyOutcome& out) {
  const std::vector<SensitivityRow>& rows = std::get<SensitivityOutcome>(out.own).rows;
  const bool has_failure =
      std::any_of(rows.begin(), rows.end(), [](const SensitivityRow& r) { return r.quantity == "W_fail_N"; });
  const char* headline = has_failure ? "W_fail_N" : "torque_Nm";
  std::vector<const SensitivityRow*> ranked;
  for (const SensitivityRow& r : rows)
    if (r.quantity == headline && r.elasticity) ranked.push_back(&r);
  std::stable_sort(ranked.begin(), ranked.end(), [](const SensitivityRow* a, const SensitivityRow* b) {
    return std::abs(*a->elasticity) > std::abs(*b->elasticity);
  });
  std::string top;
  for (std::size_t k = 0; k < std::min<std::size_t>(5, ranked.size()); ++k)
    top += fmt::format("{}{} {:+.3g}", k ? ", " : "", ranked[k]->parameter, *ranked[k]->elasticity);
  const bool temperatures = std::any_of(inputs.begin(), inputs.end(), [](const SceneInput& in) { return in.unit == "K"; });
  out.summary.push_back(fmt::format("sensitivity of {} to {} inputs; largest elasticities (relative change per relative "
                                    "change{}): {}",
                                    headline, inputs.size(),
                                    temperatures && rise > 0.0
                                        ? fmt::format("; a temperature input's per the washer's rise above the ambient, "
                                                      "{:.3g} K",
                                                      rise)
                                        : std::string(),
                                    top.empty() ? "none" : top));
}

}  // namespace

void run_sensitivity(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads) {
  out.own_part<SensitivityOutcome>();  // first: sensitivity.csv is written (empty) where the study ends early
  const Scene& scene = model.scene();
  const std::vector<SceneInput> inputs = differentiated_inputs(scene, out);

  // The state at the operating point, and J's factors there.
  std::vector<double> u;
  if (!solve_operating_point(model, out, u)) return;
  const BearingState at_point = out.states.back().state;
  const double load = model.load();
  const std::unique_ptr<SparseLu> factors = jacobian_factors(model, u);
  if (!factors) {
    out.solver_failed = true;
    out.message = fmt::format("the state at {:.6g} N has a singular Jacobian (a fold at the operating point): "
                              "it does not move smoothly with the inputs",
                              load);
    return;
  }

  const SettledFailures failures = settled_failures(model, out, progress);
  const std::vector<InputResponse> response = input_responses(model, inputs, u, load, *factors, failures, threads);
  sensitivity_rows(scene, at_point, inputs, response, failures, out);
  if (progress) progress(fmt::format("sensitivities to {} inputs", inputs.size()));
  rank_inputs(inputs, at_point.washer_mean_temperature - scene.operating.ambient, out);
}

}  // namespace twb
