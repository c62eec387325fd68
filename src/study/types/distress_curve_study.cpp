// distress_curve: one fold curve for the scene's bearing (distress_curve.h), or one per
// member of its family (study.family: the map parameters).
#include <algorithm>
#include <mutex>
#include <optional>

#include <fmt/format.h>

#include "solver/sparse_lu.h"
#include "study/searches/distress_curve.h"
#include "study/parallel/parallel.h"
#include "study/searches/study_searches.h"
#include "study/study_kind.h"
#include "twb/error_family.h"

namespace twb {
namespace {

// The members of a family are independent: on the run's threads, each with its own
// model, their outcomes joined in the family's order (the same files for any count).
void run_distress_curve(BearingModel& base, StudyOutcome& out, const StudyRun& run) {
  const int threads = run.threads;
  const std::vector<Variant> variants = parameter_variants(base.scene(), out.parameter_columns);
  DistressCurveOutcome& curves = out.own_part<DistressCurveOutcome>();
  curves.column = fold_curve_column(std::get<DistressCurveSettings>(base.scene().study.settings).curve_parameter);
  std::vector<StudyOutcome> parts(variants.size());
  std::mutex lock;
  const ProgressReport say = one_line_at_a_time(run.progress, lock);
  run_in_parallel(variants.size(), threads, [&](std::size_t i) {
    const SparseLu::Counts before = SparseLu::thread_counts();
    StudyOutcome& part = parts[i];
    try {
      BearingModel model(variants[i].scene ? *variants[i].scene : base.scene());
      // Threads the family's members leave over serve each curve's own pieces.
      // A family has one axis (the scene reader's): its member is that value.
      const std::optional<double> member =
          variants[i].parameters.empty() ? std::nullopt : std::optional<double>(variants[i].parameters.front());
      run_fold_curve(model, member, variants[i].label, part, say,
                     std::max(1, threads / int(variants.size())));
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      part.summary.push_back(fmt::format("fold curve{}: failed: {}", variants[i].label, e.what()));
    }
    part.timings.klu_factorizations +=
        SparseLu::thread_counts().factored_since(before) + part.timings.ida_factorizations;
  });
  for (StudyOutcome& part : parts) {
    out.states.insert(out.states.end(), part.states.begin(), part.states.end());
    out.distress.insert(out.distress.end(), part.distress.begin(), part.distress.end());
    // (none where the member's bearing could not be built)
    if (const DistressCurveOutcome* curve = part.distress_curve())
      curves.rows.insert(curves.rows.end(), curve->rows.begin(), curve->rows.end());
    out.summary.insert(out.summary.end(), part.summary.begin(), part.summary.end());
    out.diagnostics.insert(out.diagnostics.end(), part.diagnostics.begin(), part.diagnostics.end());
    out.timings.transients += part.timings.transients;
    out.timings.ida_steps += part.timings.ida_steps;
    out.timings.ida_factorizations += part.timings.ida_factorizations;
    out.timings.klu_factorizations += part.timings.klu_factorizations;
  }
}

void add_curve_tables(const StudyOutcome& out, std::vector<NamedTable>& tables) {
  add_distress_table(out, tables);
  const std::vector<std::string>& parameter = out.parameter_columns;
  const DistressCurveOutcome& curves = std::get<DistressCurveOutcome>(out.own);
  tables.push_back({"fold_curve", fold_curve_table(curves.rows, curves.column,
                                                   parameter.empty() ? std::string() : parameter.front())});
}

}  // namespace

extern const StudyKind kDistressCurveStudy{
    .run = run_distress_curve, .add_tables = add_curve_tables, .searches_count_their_work = true};

}  // namespace twb
