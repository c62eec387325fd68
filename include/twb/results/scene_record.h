// The resolved scene as run.json records it: every default filled in, numbers in SI with
// the unit in the key's name, as in the CSVs ("thickness_m": 0.000635, "speeds_rad_s":
// [545]), for programs that read a scene's values rather than its text.
#pragma once

#include <string>

#include "twb/scene/scene.h"

namespace twb {

// A JSON object (text).
std::string scene_record_json(const Scene& scene);

}  // namespace twb
