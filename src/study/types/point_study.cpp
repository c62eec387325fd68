// point: the bearing at the scene's operating point, with its error bars (state_error.h).
#include <memory>
#include <string>

#include "solver/sparse_lu.h"
#include "study/searches/operating_point.h"
#include "study/accuracy/state_error.h"
#include "study/study_kind.h"
#include "twb/error_family.h"

namespace twb {
namespace {

void run_point(BearingModel& model, StudyOutcome& out, const StudyRun&) {
  std::vector<double> u;
  if (!solve_operating_point(model, out, u)) return;
  const ErrorBarSettings& bars = std::get<PointSettings>(model.scene().study.settings).error_bars;
  if (bars.estimate == ErrorEstimate::none) return;
  // Its error bars, with the warning where the mesh is more than 5 % off.
  std::string why;
  try {
    const double tolerance = bars.tolerance;
    if (tolerance > 0.0) {
      // To the tolerance asked for: the meshes' estimates and their lines.
      if (refine_state_to_tolerance(model, u, out.states.back(), tolerance, out.summary, why,
                                    &out.timings.newton_iterations, &out.timings.jacobian_evaluations))
        return;
    } else if (const std::unique_ptr<BearingModel> fine = refined_model(model, why);
               fine && refine_state(model, *fine, u, out.states.back(), why, SparseLu::Ordering::minimum_degree,
                                    &out.timings.newton_iterations, &out.timings.jacobian_evaluations)) {
      const std::vector<std::string> lines = state_error_lines(model.scene(), out.states);
      out.summary.insert(out.summary.end(), lines.begin(), lines.end());
      return;
    }
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception& e) {
    why = e.what();
  }
  out.summary.push_back("no error bar: " + why);
}

}  // namespace

extern const StudyKind kPointStudy{.run = run_point, .add_tables = [](const StudyOutcome&, std::vector<NamedTable>&) {}};

}  // namespace twb
