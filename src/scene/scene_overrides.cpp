#include "scene_overrides.h"

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "scene_names.h"
#include "yaml_documents.h"
#include "twb/input_error.h"

namespace twb::scene_io {
namespace {

struct Segment {
  std::string key;
  int column;  // 1-based, in the override text
};

bool is_key_character(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

[[noreturn]] void malformed(const std::string& text, int column, const std::string& why) {
  throw InputError("--set", 0, column,
                   fmt::format("'{}' is not a valid override: {}; write path=value, e.g. "
                               "operating.load=800 N",
                               text, why),
                   text);
}

std::vector<Segment> split_path(const std::string& text, std::size_t equals) {
  std::vector<Segment> segments;
  std::size_t start = 0;
  while (true) {
    std::size_t end = text.find('.', start);
    if (end == std::string::npos || end > equals) end = equals;
    const std::string key = text.substr(start, end - start);
    if (key.empty()) malformed(text, static_cast<int>(start) + 1, "a path segment is empty");
    for (std::size_t i = 0; i < key.size(); ++i)
      if (!is_key_character(key[i]))
        malformed(text, static_cast<int>(start + i) + 1,
                  fmt::format("'{}' is not a key name (letters, digits, '_')", key));
    segments.push_back({key, static_cast<int>(start) + 1});
    if (end == equals) return segments;
    start = end + 1;
  }
}

std::string describe(const YAML::Node& node) {
  if (node.IsScalar()) return fmt::format("the value '{}'", node.Scalar());
  if (node.IsSequence()) return "a list";
  return "not a map";
}

// yaml-cpp shares one node between an anchor and its aliases ("washer: *steel"). An
// override names one path, so it must not edit the shared node in place: maps on the
// path that are shared are replaced by private copies, and the value is inserted anew.
// Their parents on the path are private already, so a map is shared when anything else
// in the tree holds it too.
//
// How many times the maps and lists of `tree` hold `target`. Each is looked into once:
// aliases can make the tree a graph with exponentially many paths through it, or a cycle
// (an alias inside its own anchor's node).
int references(const YAML::Node& tree, const YAML::Node& target) {
  std::vector<YAML::Node> seen;
  std::vector<YAML::Node> pending{tree};
  int count = 0;
  const auto hold = [&](const YAML::Node& child) {
    if (child.is(target)) ++count;
    pending.push_back(child);
  };
  while (!pending.empty()) {
    const YAML::Node node = pending.back();
    pending.pop_back();
    if (!(node.IsMap() || node.IsSequence())) continue;
    if (std::any_of(seen.begin(), seen.end(), [&](const YAML::Node& other) { return other.is(node); }))
      continue;
    seen.push_back(node);
    if (node.IsMap()) {
      for (const auto& entry : node) hold(entry.second);
    } else {
      for (const auto& item : node) hold(item);
    }
  }
  return count;
}

YAML::Node private_copy(const YAML::Node& map) {
  YAML::Node copy(YAML::NodeType::Map);
  // force_insert keeps repeated keys, so the reader still reports them.
  for (const auto& entry : map) copy.force_insert(entry.first, entry.second);
  return copy;
}

void replace(YAML::Node& map, const std::string& key, const YAML::Node& value) {
  while (map.remove(key)) {
  }
  map.force_insert(key, value);
}

}  // namespace

void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides,
                     std::deque<Origin>& origins, Provenance& provenance) {
  for (const std::string& text : overrides) {
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos) malformed(text, 0, "it has no '='");
    const std::vector<Segment> segments = split_path(text, equals);

    std::size_t value_start = text.find_first_not_of(" \t", equals + 1);
    if (value_start == std::string::npos) value_start = text.size();
    std::string path;
    for (const Segment& segment : segments) path += (path.empty() ? "" : ".") + segment.key;

    Origin& origin = origins.emplace_back();
    origin.name = fmt::format("--set {}", path);
    origin.is_file = false;
    origin.lines = {text};
    origin.key_column = segments.back().column;
    origin.value_column = static_cast<int>(value_start) + 1;

    YamlDocuments value;
    try {
      value = read_documents(text.substr(value_start));
    } catch (const YAML::Exception& error) {
      throw InputError(origin.name, 0, origin.value_column + std::max(error.mark.column, 0),
                       fmt::format("YAML syntax error in the value: {}", error.msg), text);
    }
    if (value.count > 1)
      throw InputError(origin.name, 0, origin.value_column + std::max(value.second.column, 0),
                       fmt::format("the value holds {} YAML documents; a value is one", value.count), text);

    // An empty file, or an empty section, becomes a map to hold the override.
    if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
    // A root that is not a map is reported by the scene reader, at the file.
    if (!root.IsMap()) return;

    YAML::Node parent;
    parent.reset(root);
    std::string parent_path;
    for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
      const std::string& key = segments[i].key;
      const std::string child_path = parent_path.empty() ? key : parent_path + "." + key;
      const YAML::Node child = std::as_const(parent)[key];
      if (!child.IsDefined() || child.IsNull()) {
        replace(parent, key, YAML::Node(YAML::NodeType::Map));
        provenance.assign(child_path, &origin);
      } else if (child.IsScalar() && is_library_shorthand(child_path)) {
        YAML::Node named(YAML::NodeType::Map);
        named["material"] = child;
        replace(parent, key, named);
      } else if (!child.IsMap()) {
        throw InputError(origin.name, 0, segments[i + 1].column,
                         fmt::format("'{}' is {} in the scene, not a map: it has no key '{}'",
                                     child_path, describe(child), segments[i + 1].key),
                         text);
      } else if (references(root, child) > 1) {
        replace(parent, key, private_copy(child));
      }
      const YAML::Node next = std::as_const(parent)[key];
      parent.reset(next);
      parent_path = child_path;
    }
    if (is_library_shorthand(parent_path))
      if (const std::string_view replaced = replaced_material_key(segments.back().key); !replaced.empty())
        while (parent.remove(std::string(replaced))) {
        }
    replace(parent, segments.back().key, value.first);
    provenance.assign(path, &origin);
  }
}

}  // namespace twb::scene_io
