// A measured roughness profile file (docs/physics.md section 13; docs/scenes.md "Summit
// statistics from a profile"): CSV, '#' comment lines, a header naming two columns
// with their units in brackets, then position and height at uniform spacing:
//   x [um], z [um]
//   0, 0.112
//   0.5, -0.037
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace twb::scene_io {

struct RoughnessProfile {
  std::vector<double> heights;  // m
  double spacing = 0;           // m
};

// Reads and checks the file; any fault is an InputError at its line and column in it.
RoughnessProfile read_roughness_profile(const std::string& path);

// Below this many samples a profile says little about its summits.
inline constexpr int kMinProfileSamples = 64;
inline constexpr std::uintmax_t kMaxProfileBytes = std::uintmax_t{256} << 20;

}  // namespace twb::scene_io
