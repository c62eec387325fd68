#include "study/results_files.h"

#include "results/atomic_file.h"
#include "results/run_record.h"
#include "twb/results/cycle_state.h"
#include "twb/results/fields_table.h"
#include "twb/results/worn_washer.h"
#include "twb/scene/scene_loader.h"

namespace twb {

void write_study_results(const std::filesystem::path& dir, const std::string& scene_path, const Scene& scene,
                         const UnknownLayout& layout, const StudyOutcome& outcome, int digits) {
  for (const NamedTable& table : study_tables(outcome, scene.study.type()))
    write_file_atomically(dir / (table.name + ".csv"), table.table.csv(digits));
  write_state_fields(dir, outcome.states, digits);
  // A completed duty cycle's end, for the next part of a long cycle (--continue-from).
  // (None from an unfinished one: no earlier run's end may be left to look like this one's.)
  if (const DutyCycleOutcome* cycle = outcome.duty_cycle(); cycle && cycle->end)
    write_file_atomically(dir / "cycle_end_state.json", cycle_state_json(*cycle->end));
  else
    std::filesystem::remove(dir / "cycle_end_state.json");
  // The washer a life wore, for a life to go on or another study of it (--continue-from).
  if (const LifeOutcome* life = outcome.life(); life && !life->worn.empty())
    write_file_atomically(dir / "worn_washer.json", worn_washer_json(life->worn.back()));
  else
    std::filesystem::remove(dir / "worn_washer.json");
  const std::string verdict = outcome.solver_failed ? "solver failure: " + outcome.message
                                                    : (outcome.message.empty() ? "ok" : outcome.message);
  write_file_atomically(dir / "run.json",
                        run_json(scene_path, describe_scene(scene), layout, outcome.timings, verdict,
                                 scene.study.speeds_in_rpm ? "rpm" : "rad/s"));
}

}  // namespace twb
