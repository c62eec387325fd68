#include "study/sensitivity.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "solver/continuation_metric.h"
#include "solver/fold_system.h"
#include "solver/sparse_lu.h"
#include "study/distress_search.h"
#include "study/crossing_response.h"
#include "study/parallel.h"
#include "twb/results/distress_table.h"
#include "study/steady_solver.h"
#include "study_support.h"
#include "twb/error_family.h"
#include "twb/scene/input_error.h"
#include "twb/scene/scene_inputs.h"

namespace twb {

namespace {

constexpr double kCelsius = 273.15;

double dot(std::span<const double> a, std::span<const double> b) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
  return s;
}

// What one input moves: each state quantity's derivative, W_d's and each crossing's.
struct InputResponse {
  std::vector<double> state;
  std::optional<double> fold_load;
  std::vector<std::optional<double>> crossing_loads;
  double step = 0.0;
  std::string why;  // where the input could not be differentiated
};

}  // namespace

std::vector<StateQuantity> state_quantities(const BearingState& s) {
  return {{"torque_Nm", s.torque, false},
          {"f_eff", s.f_eff, false},
          {"T_mean_C", s.washer_mean_temperature, true},
          {"T_max_C", s.max_film_temperature, true},
          {"hmin_over_sigma", s.hmin_over_sigma, false},
          {"fluid_share", s.fluid_share, false}};
}

std::vector<double> state_derivatives(InputNeighbours& n, std::span<const double> u, double load, const SparseLu& lu,
                                      std::mutex& solve_lock) {
  std::vector<double> u_p = residual_derivative(n, u, load);
  {
    const std::lock_guard<std::mutex> hold(solve_lock);
    lu.solve(u_p);  // J⁻¹F_p: the state moves by −u_p per unit of p
  }
  return neighbour_derivative(n.step, [&](std::size_t k) {
    std::vector<double> moved(u.begin(), u.end());
    for (std::size_t j = 0; j < moved.size(); ++j) moved[j] -= InputNeighbours::kOffsets[k] * n.step * u_p[j];
    n.at[k]->set_load(n.load_at(k, load));
    std::vector<double> values;
    for (const StateQuantity& q : state_quantities(n.at[k]->describe(moved))) values.push_back(q.value);
    return values;
  });
}

void run_sensitivity(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads) {
  const Scene& scene = model.scene();
  const Study& st = scene.study;
  auto say = [&](const std::string& s) {
    if (progress) progress(s);
  };
  std::vector<SceneInput> inputs;
  if (st.parameters.empty())
    inputs = scene.inputs;
  else
    for (const std::string& path : st.parameters) inputs.push_back(scene_input(scene, path));

  // The state at the operating point, and J's factors there.
  std::vector<double> u;
  if (!solve_operating_point(model, out, u)) return;
  const BearingState at_point = out.states.back().state;
  const double load = model.load();
  const auto n = std::size_t(model.size());
  std::vector<double> f(n), jac(std::size_t(model.pattern().nnz()));
  model.evaluate(u, f, jac);
  SparseLu lu(model.pattern(), SparseLu::Ordering::minimum_degree);
  if (!lu.factor(jac)) {
    out.solver_failed = true;
    out.message = fmt::format("the state at {:.6g} N has a singular Jacobian (a fold at the operating point): "
                              "it does not move smoothly with the inputs",
                              load);
    return;
  }

  // The fold in the study's load range, and its left null vector.
  std::optional<FoldPoint> fold;
  std::vector<double> psi;
  double psi_load = 0.0;  // ψᵀF_W
  std::vector<SettledCrossing> crossings;  // each criterion the branch crosses, settled
  std::optional<double> failure_load;
  if (st.load_end > 0.0) {
    DistressSearchSettings settings;
    settings.load_start = st.load_start;
    settings.load_end = st.load_end;
    settings.bracket_width = st.bracket_width;
    settings.march_past_distress = false;
    DistressSearch found = search_distress(model, settings, progress);
    add_search_work(out.timings, found.counts);
    out.distress.push_back(found.row);
    if (found.fold && found.fold_proven) {
      // The search settles the fold's load to its bracket, not its state to the residual's
      // tolerance; ψ and F_p need the fold itself (off it, ψ is no left null vector and
      // the derivative is off by the distance).
      fold = locate_fold_near(model, found.fold->u, found.fold->lambda, found.fold->null_vector,
                              newton_settings(scene));
      if (fold->u.empty()) {
        out.summary.push_back("sensitivity: the fold could not be located to the solver's tolerance (" + fold->message +
                              "): no derivatives of W_d");
        fold.reset();
      }
    }
    if (fold) {
      const ParameterScope at_fold(model, fold->lambda);
      std::vector<double> f_load(n);
      model.parameter_derivative(fold->u, f_load);
      const ContinuationMetric metric = ContinuationMetric::of(model, std::abs(fold->lambda));
      const FoldSystem system(model, metric, f_load, fold->null_vector);
      std::vector<double> x = fold->u;
      x.push_back(fold->lambda / metric.parameter_scale());
      psi = system.left_null_vector(x);
      if (!psi.empty()) psi_load = dot(psi, f_load);
    }
    if (!psi.empty() && !(std::abs(psi_load) > 0.0)) psi.clear();
    for (std::size_t c = 0; c < found.crossing_states.size(); ++c) {
      if (found.crossing_states[c].second.empty()) continue;
      std::string why;
      std::optional<SettledCrossing> settled = settle_crossing(model, kFailureCriteria[c], found.crossing_states[c].first,
                                                               found.crossing_states[c].second, why);
      if (settled)
        crossings.push_back(std::move(*settled));
      else
        out.summary.push_back(fmt::format("sensitivity: no derivatives of {}: {}",
                                          criterion_column(kFailureCriteria[c]), why));
    }
    failure_load = found.row.failure_load;
    if (!found.fold || !found.fold_proven)
      out.summary.push_back("sensitivity: no fold in the load range, so no derivatives of W_d (" + found.row.method + ")");
    else if (fold && psi.empty())
      out.summary.push_back("sensitivity: the fold's left null vector could not be found: no derivatives of W_d");
  }

  // Each input on its own models; J's back-substitutions one at a time (KLU's solve
  // writes into its factors' workspace).
  std::vector<InputResponse> response(inputs.size());
  std::mutex solve_lock;
  run_in_parallel(inputs.size(), threads, [&](std::size_t i) {
    InputResponse& r = response[i];
    try {
      InputNeighbours nb = input_neighbours(model, inputs[i]);
      r.step = nb.step;
      r.state = state_derivatives(nb, u, load, lu, solve_lock);
      // The failure loads do not depend on the operating load.
      if (inputs[i].path != kLoadInput)
        for (const SettledCrossing& c : crossings) r.crossing_loads.push_back(crossing_load_derivative(nb, c, solve_lock));
      if (fold && !psi.empty() && inputs[i].path != kLoadInput)
        r.fold_load = -dot(psi, residual_derivative(nb, fold->u, fold->lambda)) / psi_load;
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      r.why = e.what();
    }
  });

  const std::vector<StateQuantity> quantities = state_quantities(at_point);
  const double ambient = scene.operating.ambient;
  auto row = [&](const char* name, double value, double reference, const SceneInput& in, double derivative, double step) {
    SensitivityRow& r = out.sensitivity.emplace_back();
    r.quantity = name;
    r.value = value;
    r.parameter = in.path;
    r.parameter_value = in.value;
    r.parameter_unit = in.unit;
    r.derivative = derivative;
    if (reference != 0.0 && in.value != 0.0) r.elasticity = derivative * in.value / reference;
    r.step = step;
  };
  for (std::size_t k = 0; k < quantities.size(); ++k)
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      if (response[i].state.empty()) continue;
      const StateQuantity& q = quantities[k];
      row(q.name, q.temperature ? q.value - kCelsius : q.value, q.temperature ? q.value - ambient : q.value, inputs[i],
          response[i].state[k], response[i].step);
    }
  if (fold)
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (response[i].fold_load) row("W_d_N", fold->lambda, fold->lambda, inputs[i], *response[i].fold_load, response[i].step);
  for (std::size_t c = 0; c < crossings.size(); ++c) {
    const std::string name = criterion_column(crossings[c].kind);
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (c < response[i].crossing_loads.size() && response[i].crossing_loads[c])
        row(name.c_str(), crossings[c].load, crossings[c].load, inputs[i], *response[i].crossing_loads[c], response[i].step);
  }
  // W_fail's rows: those of the failure load that sets it (docs/physics.md section 8).
  std::string setting;
  if (failure_load) {
    auto sets = [&](double w) { return std::abs(w - *failure_load) <= st.bracket_width * *failure_load; };
    if (fold && !psi.empty() && sets(fold->lambda)) setting = "W_d_N";
    for (const SettledCrossing& c : crossings)
      if (setting.empty() && sets(c.load)) setting = criterion_column(c.kind);
  }
  for (std::size_t k = 0, end = out.sensitivity.size(); k < end && !setting.empty(); ++k)
    if (out.sensitivity[k].quantity == setting) {
      SensitivityRow copy = out.sensitivity[k];
      copy.quantity = "W_fail_N";
      out.sensitivity.push_back(std::move(copy));
    }
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (!response[i].why.empty()) out.summary.push_back(fmt::format("sensitivity: {}: not differentiated: {}", inputs[i].path, response[i].why));

  // The inputs that matter most to the answer: W_fail's where there is one, else the torque's.
  const char* headline = !setting.empty() ? "W_fail_N" : "torque_Nm";
  std::vector<const SensitivityRow*> ranked;
  for (const SensitivityRow& r : out.sensitivity)
    if (r.quantity == headline && r.elasticity) ranked.push_back(&r);
  std::stable_sort(ranked.begin(), ranked.end(), [](const SensitivityRow* a, const SensitivityRow* b) {
    return std::abs(*a->elasticity) > std::abs(*b->elasticity);
  });
  std::string top;
  for (std::size_t k = 0; k < std::min<std::size_t>(5, ranked.size()); ++k)
    top += fmt::format("{}{} {:+.3g}", k ? ", " : "", ranked[k]->parameter, *ranked[k]->elasticity);
  say(fmt::format("sensitivities to {} inputs", inputs.size()));
  out.summary.push_back(fmt::format("sensitivity of {} to {} inputs; largest elasticities (relative change per relative "
                                    "change): {}",
                                    headline, inputs.size(), top.empty() ? "none" : top));
}

}  // namespace twb
