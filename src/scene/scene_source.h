// Where each piece of a scene's text came from (the file, or a `--set` override), so
// that an error can point at it.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <yaml-cpp/mark.h>

namespace twb::scene_io {

struct Origin {
  std::string name;                // the file's path, or "--set operating.load"
  bool is_file = true;
  std::vector<std::string> lines;  // the file's lines, or the one override text
  // Overrides only: 1-based columns, in the override text, of the last path segment
  // and of the value. The value's YAML marks count from the value's first character.
  int key_column = 0;
  int value_column = 0;
};

// Text belongs to the file unless an override replaced it, or created the map that
// holds it; a node inherits its parent's origin otherwise.
class Provenance {
 public:
  explicit Provenance(const Origin* file) : file_(file) {}
  const Origin* file() const { return file_; }
  void assign(const std::string& path, const Origin* origin) { by_path_[path] = origin; }
  const Origin* origin_of(const std::string& path, const Origin* parent) const {
    const auto found = by_path_.find(path);
    return found != by_path_.end() ? found->second : parent;
  }
  // Every quantity the readers took from the text, as they took it (SI value, SI unit):
  // what makes each of the scene's numbers a parameter (Scene::inputs).
  struct ReadQuantity {
    std::string path;
    double value;
    std::string_view unit;
  };
  void note_quantity(const std::string& path, double value, std::string_view unit) const {
    read_.push_back({path, value, unit});
  }
  const std::vector<ReadQuantity>& quantities_read() const { return read_; }
  // A file a value names, as the reader resolved it (relative to the file that named
  // it): the tree read again elsewhere must name the same file.
  void note_resolved_path(const std::string& path, std::string resolved) const {
    resolved_paths_.emplace_back(path, std::move(resolved));
  }
  const std::vector<std::pair<std::string, std::string>>& resolved_paths() const { return resolved_paths_; }

 private:
  const Origin* file_;
  std::map<std::string, const Origin*> by_path_;
  // What the readers saw, noted as they read (the readers hold the provenance const).
  mutable std::vector<ReadQuantity> read_;
  mutable std::vector<std::pair<std::string, std::string>> resolved_paths_;
};

// Throws the InputError for text at `mark` of `origin`. A key node created by an override
// has no mark: `at_key` then points at the override's last path segment.
[[noreturn]] void fail_at(const Origin& origin, const YAML::Mark& mark, bool at_key,
                          const std::string& message);

// Lines of a text without their line ends (CRLF files included).
std::vector<std::string> split_lines(const std::string& text);

}  // namespace twb::scene_io
