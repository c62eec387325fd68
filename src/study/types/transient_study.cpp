// transient: the steady state at load_start, then IDA's march of the step to load_end
// (load_step_march.h): settled, or run away by thermo-viscous distress.
#include <fmt/format.h>

#include "study/searches/load_step_march.h"
#include "study/searches/operating_point.h"
#include "study/searches/steady_solver.h"
#include "study/study_kind.h"
#include "study/study_support.h"

namespace twb {
namespace {

void run_transient(BearingModel& model, StudyOutcome& out, const StudyRun& run) {
  const LoadStepSettings& step = std::get<LoadStepSettings>(model.scene().study.settings);
  const NewtonSettings newton = newton_settings(model.scene());
  const LoadRange& loads = step.loads;
  model.set_load(loads.start);
  SteadySolver solver(model, newton);
  std::vector<double> u;
  const SteadyReport rep = solver.solve_cold(u);
  if (!rep.converged) {
    out.solver_failed = true;
    out.message = fmt::format("no steady state before the step, at {:.6g} N: {}", loads.start, rep.message);
    return;
  }
  out.states.push_back(recorded_state(model, u, rep));
  if (run.progress) run.progress(fmt::format("steady at {:.6g} N; stepping to {:.6g} N", loads.start, loads.end));
  StepMarch march = march_load_step(model, u, loads.start, loads.end, TransientSettings{}, newton, step.duration);
  out.timings.newton_iterations += rep.iterations + march.newton_iterations;
  out.timings.jacobian_evaluations += rep.jacobian_evaluations;
  out.timings.transients += 1;
  out.timings.ida_steps += march.ida_steps;
  out.timings.ida_factorizations += march.ida_factorizations;
  out.trajectory = std::move(march.trajectory);
  model.set_load(loads.end);  // the march's last state is at the load it stepped to
  SolvedState last = solved_state(model, march.state);
  last.converged = march.settled;
  last.iterations = march.newton_iterations;
  std::vector<double> r(march.state.size());
  model.evaluate(march.state, r, {});
  last.residual = max_norm(r);
  last.wall_ms = march.wall_ms;
  out.states.push_back(last);
  out.message = "transient: " + march.message;
  // A march that never started has no trajectory to report: the study failed.
  if (!march.started) out.solver_failed = true;
}

}  // namespace

extern const StudyKind kTransientStudy{.run = run_transient,
                                       .add_tables = [](const StudyOutcome&, std::vector<NamedTable>&) {}};

}  // namespace twb
