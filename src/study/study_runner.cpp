#include "twb/study/study_runner.h"

#include <chrono>
#include <stdexcept>

#include <fmt/format.h>

#include "twb/solver/steady_solver.h"

namespace twb {

namespace {

NewtonSettings newton_settings(const Scene& s) {
  NewtonSettings n;
  n.residual_tolerance = s.solver.residual_tolerance;
  n.step_tolerance = s.solver.step_tolerance;
  n.max_iterations = s.solver.max_iterations;
  return n;
}

SolvedState record(const BearingModel& model, const std::vector<double>& u, const SteadyReport& rep) {
  SolvedState row;
  row.state = model.describe(u);
  row.converged = rep.converged;
  row.iterations = rep.iterations;
  row.residual = rep.residual_norm;
  row.wall_ms = rep.wall_ms;
  return row;
}

}  // namespace

StudyOutcome run_study(BearingModel& model, const ProgressReport& progress) {
  const Scene& scene = model.scene();
  StudyOutcome out;
  SteadySolver solver(model, newton_settings(scene));
  const auto t0 = std::chrono::steady_clock::now();
  auto note = [&](const SteadyReport& rep) {
    out.timings.newton_iterations += rep.iterations;
    out.timings.jacobian_evaluations += rep.jacobian_evaluations;
  };

  switch (scene.study.type) {
    case StudyType::point: {
      std::vector<double> u;
      const SteadyReport rep = solver.solve_cold(u);
      note(rep);
      if (!rep.converged) {
        out.solver_failed = true;
        out.message = fmt::format("no steady state at {:.6g} N: {}", model.load(), rep.message);
        break;
      }
      out.states.push_back(record(model, u, rep));
      break;
    }
    case StudyType::load_sweep: {
      // Natural-parameter continuation in load, each state warm-started from the last.
      const Study& st = scene.study;
      std::vector<double> u;
      for (int k = 0; k < st.load_steps; ++k) {
        const double load = st.load_start + (st.load_end - st.load_start) * k / (st.load_steps - 1);
        model.set_load(load);
        const SteadyReport rep = (k == 0) ? solver.solve_cold(u) : solver.solve(u);
        note(rep);
        if (!rep.converged) {
          out.solver_failed = out.states.empty();
          out.message = fmt::format("the steady branch was lost at {:.6g} N: {}", load, rep.message);
          break;
        }
        out.states.push_back(record(model, u, rep));
        if (progress)
          progress(fmt::format("[{}/{}] {:.1f} N solved in {:.1f} ms", k + 1, st.load_steps, load, rep.wall_ms));
      }
      break;
    }
    case StudyType::distress_map:
    case StudyType::transient:
      throw std::invalid_argument("this version of twb runs the 'point' and 'load_sweep' studies only");
  }
  out.timings.states = int(out.states.size());
  out.timings.solve_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace twb
