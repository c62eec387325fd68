// A benchmark's command-line lists, and a mesh given as RxC (e.g. 9x66) as scene overrides.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace twb::bench {

// A comma-separated list on the command line (meshes, tolerances, speeds).
inline std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> parts;
  std::stringstream in(list);
  for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
  return parts;
}

inline std::vector<std::string> mesh_overrides(const std::string& mesh) {
  const auto x = mesh.find('x');
  if (x == std::string::npos) throw std::invalid_argument("a mesh is RxC, e.g. 9x66, not " + mesh);
  return {"mesh.radial_nodes=" + mesh.substr(0, x), "mesh.circumferential_nodes=" + mesh.substr(x + 1)};
}

}  // namespace twb::bench
