// A node of a scene's YAML tree by its dotted path, as the readers name values
// ("surfaces.asperities.profile", "surfaces.asperities.profile[1]").
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

namespace twb::scene_io {

// The node at `path` in `root`, a handle into the tree (assigning to it writes there);
// none where a segment is missing. Creates nothing.
inline std::optional<YAML::Node> node_at(const YAML::Node& root, std::string_view path) {
  YAML::Node node;
  node.reset(root);  // reset, not assignment: assigning a yaml-cpp node writes into its tree
  while (!path.empty()) {
    const std::size_t dot = path.find('.');
    const std::string_view segment = path.substr(0, dot);
    path = dot == std::string_view::npos ? std::string_view() : path.substr(dot + 1);
    const std::size_t bracket = segment.find('[');
    const std::string key(segment.substr(0, bracket));
    if (!node.IsMap() || !node[key]) return std::nullopt;
    YAML::Node child = node[key];
    if (bracket != std::string_view::npos) {
      const std::size_t index = std::stoul(std::string(segment.substr(bracket + 1)));
      if (!child.IsSequence() || index >= child.size()) return std::nullopt;
      YAML::Node item = child[index];
      child.reset(item);
    }
    node.reset(child);
  }
  return node;
}

}  // namespace twb::scene_io
