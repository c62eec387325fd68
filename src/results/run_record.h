// run.json: what was run (the resolved scene), with which versions, and how long it took.
#pragma once

#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "twb/results/run_timings.h"

namespace twb {

// The versions of twb and each library it was built with.
std::vector<std::pair<std::string, std::string>> library_versions();

// resolved_scene_yaml: the loader's describe_scene() text; speed_unit: "rpm" where the
// scene gave its speeds so (the figures follow it), else "rad/s".
std::string run_json(const std::string& scene_path, const std::string& resolved_scene_yaml,
                     const UnknownLayout& layout, const RunTimings& timings, const std::string& outcome,
                     const std::string& speed_unit = "rad/s");

}  // namespace twb
