// `twb run --set path=value`: edits of the scene tree made before validation, so that an
// override is checked exactly like the file and its errors point at the override.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "scene_source.h"

namespace twb::scene_io {

// Sets each "dotted.path=value" (value parsed as YAML) in `root`, creating missing maps,
// later overrides winning. `origins` receives one Origin per override (a deque, so the
// pointers `provenance` keeps stay valid). Throws InputError for a malformed override.
void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides,
                     std::deque<Origin>& origins, Provenance& provenance);

}  // namespace twb::scene_io
