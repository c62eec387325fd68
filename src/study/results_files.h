// A study's results directory as `twb run` writes it and twb.run too (docs/scenes.md,
// "output"): every table of the study (study_tables) as CSV, each state's fields
// (output.fields), a completed duty cycle's end state, and run.json last, each file
// atomically, so that a directory without run.json holds no complete run.
#pragma once

#include <filesystem>
#include <string>

#include "model/unknown_layout.h"
#include "twb/scene/scene.h"
#include "twb/study/study_outcome.h"

namespace twb {

// Into `dir` (made ready by ResultsDirectory: created, locked, emptied of an earlier run's
// files); scene_path is the scene file as run.json names it; digits the CSV's significant
// digits (10; 17 to the bit).
void write_study_results(const std::filesystem::path& dir, const std::string& scene_path, const Scene& scene,
                         const UnknownLayout& layout, const StudyOutcome& outcome, int digits);

}  // namespace twb
