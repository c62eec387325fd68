// run.json: what was run (the resolved scene), with which versions, and how long it took.
#pragma once

#include <string>
#include <vector>

#include "twb/model/bearing_model.h"

namespace twb {

struct RunTimings {
  double total_ms = 0.0, setup_ms = 0.0, solve_ms = 0.0;
  int states = 0;
  long newton_iterations = 0, jacobian_evaluations = 0;
  // Distress searches: their transients, IDA steps and the KLU factorizations inside IDA;
  // and every KLU factorization of the study, twb's own and IDA's.
  long transients = 0, ida_steps = 0, ida_factorizations = 0, klu_factorizations = 0;
};

// The versions of twb and each library it was built with.
std::vector<std::pair<std::string, std::string>> library_versions();

// resolved_scene_yaml: the loader's describe_scene() text.
std::string run_json(const std::string& scene_path, const std::string& resolved_scene_yaml,
                     const UnknownLayout& layout, const RunTimings& timings, const std::string& outcome);

}  // namespace twb
