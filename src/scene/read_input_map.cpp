// A study's map from scene paths of inputs to what it says about each (a reliability's
// `inputs`, a calibration's `fit`): each entry with the input it names, located errors for
// an empty map, a path that names no input, or one the study does not take.
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scene_sections.h"
#include "twb/scene/scene_inputs.h"

namespace twb::scene_io {

std::vector<InputEntry> input_entries(const Node& map_node, const Scene& out, std::string_view none,
                                      std::string_view example,
                                      const std::function<std::string(const std::string&)>& not_taken) {
  if (!map_node.yaml().IsMap() || map_node.yaml().size() == 0)
    map_node.fail(fmt::format("{}: {}; give a map from input paths to {}", map_node.path(),
                              map_node.yaml().IsMap() ? std::string(none) : map_node.describe_content(), example));
  std::vector<std::string> keys;
  for (const auto& kv : map_node.yaml()) keys.push_back(kv.first.as<std::string>());
  const MapReader map(map_node, std::vector<std::string_view>(keys.begin(), keys.end()));
  std::vector<InputEntry> entries;
  for (const std::string& path : map.keys()) {
    const Node entry = map.get(path, "");
    if (const std::string why = not_taken(path); !why.empty()) entry.fail(fmt::format("{}: {}", entry.path(), why));
    // Both studies that read such a map move their inputs along derivatives.
    if (const std::string why = stepwise_input(path); !why.empty())
      entry.fail(fmt::format("{}: {}; give a continuous input, or map the bearing over it (type: distress_map)",
                             entry.path(), why));
    try {
      entries.push_back({entry, scene_input(out, path)});
    } catch (const std::invalid_argument& e) {
      entry.fail(fmt::format("{}: {}", entry.path(), e.what()));
    }
  }
  return entries;
}

}  // namespace twb::scene_io
