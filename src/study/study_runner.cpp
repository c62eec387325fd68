#include "twb/study/study_runner.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "load_step_march.h"
#include "study_support.h"
#include "twb/solver/steady_solver.h"
#include "twb/study/distress_search.h"

namespace twb {

namespace {

using Clock = std::chrono::steady_clock;

SolvedState record(const BearingModel& model, const std::vector<double>& u, const SteadyReport& rep) {
  SolvedState row = solved_state(model, u);
  row.converged = rep.converged;
  row.iterations = rep.iterations;
  row.residual = rep.residual_norm;
  row.wall_ms = rep.wall_ms;
  return row;
}

void run_point(BearingModel& model, StudyOutcome& out) {
  SteadySolver solver(model, newton_settings(model.scene()));
  std::vector<double> u;
  const SteadyReport rep = solver.solve_cold(u);
  out.timings.newton_iterations += rep.iterations;
  out.timings.jacobian_evaluations += rep.jacobian_evaluations;
  if (!rep.converged) {
    out.solver_failed = true;
    out.message = fmt::format("no steady state at {:.6g} N: {}", model.load(), rep.message);
    return;
  }
  out.states.push_back(record(model, u, rep));
}

void run_load_sweep(BearingModel& model, StudyOutcome& out, const ProgressReport& progress) {
  const Study& st = model.scene().study;
  DistressSearchSettings s;
  s.load_start = st.load_start;
  s.load_end = st.load_end;
  s.bracket_width = st.bracket_width;
  for (int k = 0; k < st.load_steps; ++k)
    s.grid.push_back(st.load_start + (st.load_end - st.load_start) * k / (st.load_steps - 1));
  s.continue_past_distress = true;
  DistressSearch found = search_distress(model, s, progress);
  out.states = std::move(found.states);
  out.trajectory = std::move(found.runaway);
  out.solver_failed = found.failed;
  out.message = found.message;
  if (!found.failed) out.distress.push_back(found.row);
}

// Applies a distress map's second parameter to a scene.
Scene with_parameter(Scene scene, MapParameter p, double value) {
  switch (p) {
    case MapParameter::friction_coefficient:
      scene.friction.coefficient = value;
      break;
    case MapParameter::gear_tilt:
      scene.gear.tilt = value;
      break;
    case MapParameter::roughness: {
      // Every surface gets Rq = value, Ra in the same ratio; the summits follow a texture
      // scaled in height by k (McCool's spectral moments m0, m2, m4 all scale with k²):
      // σs ∝ k, R ∝ 1/k, η unchanged (MODEL.md section 4).
      const double before = std::hypot(scene.carrier.roughness.rq, scene.washer.roughness.rq);
      for (Component* c : {&scene.carrier, &scene.washer, &scene.gear}) {
        c->roughness.ra *= value / c->roughness.rq;
        c->roughness.rq = value;
      }
      const double k = std::hypot(value, value) / before;
      scene.asperities.summit_sigma *= k;
      scene.asperities.summit_radius /= k;
      break;
    }
    case MapParameter::none:
      break;
  }
  return scene;
}

void run_distress_map(const BearingModel& base, StudyOutcome& out, const ProgressReport& progress) {
  const Study& st = base.scene().study;
  const bool axis = st.parameter != MapParameter::none;
  if (axis)
    out.parameter_column = st.parameter == MapParameter::gear_tilt   ? "gear_tilt_rad"
                           : st.parameter == MapParameter::roughness ? "roughness_Rq_m"
                                                                     : "friction_coefficient";
  const std::vector<double> values = axis ? st.parameter_values : std::vector<double>{0.0};
  const std::size_t total = values.size() * st.speeds.size();
  std::size_t done = 0;
  const auto t0 = Clock::now();
  for (double value : values) {
    BearingModel model(axis ? with_parameter(base.scene(), st.parameter, value) : base.scene());
    for (double speed : st.speeds) {
      model.set_speed(speed);
      if (progress)
        progress(fmt::format("[{}/{}] {:.6g} rad/s{}", done + 1, total, speed,
                             axis ? fmt::format(", {} = {:.6g}", out.parameter_column, value) : ""));
      DistressSearchSettings s;
      s.load_start = st.load_start;
      s.load_end = st.load_end;
      s.bracket_width = st.bracket_width;
      DistressSearch found;
      try {
        found = search_distress(model, s, progress);
      } catch (const std::exception& e) {
        // One point that fails must not lose the map's other rows.
        found.failed = true;
        found.row.speed = speed;
        found.row.method = std::string("solver failure: ") + e.what();
        found.message = found.row.method;
      }
      if (axis) found.row.parameter = value;
      out.distress.push_back(found.row);
      // The cool branch's states are results too (f_eff, temperature against load).
      for (std::size_t k = 0; k < found.cool_states; ++k) out.states.push_back(found.states[k]);
      if (found.failed) out.message += (out.message.empty() ? "" : "; ") + found.message;
      ++done;
      if (progress) {
        const double per_point = elapsed_ms(t0) / double(done);
        progress(fmt::format("[{}/{}] done: W_d = {} ({}); about {:.0f} s left", done, total,
                             found.row.distress_load ? fmt::format("{:.2f} N", *found.row.distress_load) : "none",
                             found.row.method, per_point * double(total - done) / 1000.0));
      }
    }
  }
}

void run_transient(BearingModel& model, StudyOutcome& out, const ProgressReport& progress) {
  const Study& st = model.scene().study;
  const NewtonSettings newton = newton_settings(model.scene());
  model.set_load(st.load_start);
  SteadySolver solver(model, newton);
  std::vector<double> u;
  const SteadyReport rep = solver.solve_cold(u);
  if (!rep.converged) {
    out.solver_failed = true;
    out.message = fmt::format("no steady state before the step, at {:.6g} N: {}", st.load_start, rep.message);
    return;
  }
  out.states.push_back(record(model, u, rep));
  if (progress) progress(fmt::format("steady at {:.6g} N; stepping to {:.6g} N", st.load_start, st.load_end));
  StepMarch march = march_load_step(model, u, st.load_end, TransientSettings{}, newton, st.duration);
  out.trajectory = std::move(march.trajectory);
  SolvedState last = solved_state(model, march.state);
  last.converged = march.settled;
  last.iterations = march.newton_iterations;
  std::vector<double> r(march.state.size());
  model.evaluate(march.state, r, {});
  last.residual = max_norm(r);
  last.wall_ms = march.wall_ms;
  out.states.push_back(last);
  out.message = "transient: " + march.message;
}

}  // namespace

StudyOutcome run_study(BearingModel& model, const ProgressReport& progress) {
  StudyOutcome out;
  const auto t0 = Clock::now();
  switch (model.scene().study.type) {
    case StudyType::point:
      run_point(model, out);
      break;
    case StudyType::load_sweep:
      run_load_sweep(model, out, progress);
      break;
    case StudyType::distress_map:
      run_distress_map(model, out, progress);
      break;
    case StudyType::transient:
      run_transient(model, out, progress);
      break;
  }
  out.timings.states = int(out.states.size());
  out.timings.solve_ms = elapsed_ms(t0);
  return out;
}

}  // namespace twb
