// Results are written atomically: into a temporary file beside the target, flushed to
// disk, then renamed over it, so a crash never leaves a half-written result.
#pragma once

#include <filesystem>
#include <string_view>

namespace twb {

void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace twb
