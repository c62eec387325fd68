// A mesh given on a benchmark's command line as RxC (e.g. 9x66), as scene overrides.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace twb::bench {

inline std::vector<std::string> mesh_overrides(const std::string& mesh) {
  const auto x = mesh.find('x');
  if (x == std::string::npos) throw std::invalid_argument("a mesh is RxC, e.g. 9x66, not " + mesh);
  return {"mesh.radial_nodes=" + mesh.substr(0, x), "mesh.circumferential_nodes=" + mesh.substr(x + 1)};
}

}  // namespace twb::bench
