#include "scene_extends.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "scene_names.h"

namespace twb::scene_io {
namespace {

namespace fs = std::filesystem;

std::string child(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

const Origin* origin_in(const SceneTree& tree, const std::string& path, const Origin* parent) {
  const auto found = tree.origins.find(path);
  return found != tree.origins.end() ? found->second : parent;
}

// A subtree taken whole from `tree`: its root's origin, and those of its descendants.
void keep_origins(const SceneTree& tree, const std::string& path, const Origin* origin,
                  std::map<std::string, const Origin*>& out) {
  out[path] = origin;
  for (const auto& [p, o] : tree.origins)
    if (p.size() > path.size() && p.compare(0, path.size(), path) == 0 && (p[path.size()] == '.' || p[path.size()] == '['))
      out[p] = o;
}

// Maps merge key by key; anything else the file writes replaces the base's. Key nodes
// are the originals (force_insert keeps them), so errors about a key still point at it.
YAML::Node merge(const YAML::Node& base, const SceneTree& base_tree, const YAML::Node& own, const SceneTree& own_tree,
                 const std::string& path, const Origin* base_origin, const Origin* own_origin,
                 std::map<std::string, const Origin*>& origins) {
  YAML::Node out(YAML::NodeType::Map);
  // Key and value nodes share their data with the tree (marks included).
  std::vector<std::pair<YAML::Node, YAML::Node>> own_entries;
  for (const auto& entry : own) own_entries.emplace_back(entry.first, entry.second);
  std::vector<bool> used(own_entries.size(), false);
  for (const auto& entry : base) {
    const YAML::Node base_key = entry.first, base_value = entry.second;
    const bool named = base_key.IsScalar();
    const std::string key = named ? base_key.Scalar() : "?";
    const std::string p = child(path, key);
    const Origin* bo = origin_in(base_tree, p, base_origin);
    std::size_t match = own_entries.size();
    for (std::size_t k = 0; named && k < own_entries.size() && match == own_entries.size(); ++k)
      if (!used[k] && own_entries[k].first.IsScalar() && own_entries[k].first.Scalar() == key) match = k;
    if (match == own_entries.size()) {
      const std::string_view replaced_by = is_library_shorthand(path) ? replaced_material_key(key) : "";
      const auto gives = [&](std::string_view k) {
        return std::any_of(own_entries.begin(), own_entries.end(),
                           [&](const auto& e) { return e.first.IsScalar() && e.first.Scalar() == k; });
      };
      if (!replaced_by.empty() && gives(replaced_by)) continue;
      out.force_insert(base_key, base_value);
      keep_origins(base_tree, p, bo, origins);
      continue;
    }
    used[match] = true;
    const YAML::Node value = own_entries[match].second;
    const Origin* oo = origin_in(own_tree, p, own_origin);
    // A map tagged '!replace' stands for itself, without the base's keys.
    const bool merges = value.IsMap() && value.Tag() != kReplaceTag;
    // The base's material named alone, opened so that the file's fields go over it.
    // (A new node: assigning to a yaml-cpp node that shares the base's would rewrite the
    // base's own value.)
    const bool opened = merges && base_value.IsScalar() && is_library_shorthand(p);
    YAML::Node base_map(opened ? YAML::Node(YAML::NodeType::Map) : base_value);
    if (opened) base_map["material"] = base_value;
    if (base_map.IsMap() && merges) {
      out.force_insert(own_entries[match].first, merge(base_map, base_tree, value, own_tree, p, bo, oo, origins));
      origins[p] = oo;
    } else {
      out.force_insert(own_entries[match].first, value);
      keep_origins(own_tree, p, oo, origins);
    }
  }
  // The file's other keys, duplicates included (the section readers reject those, here).
  for (std::size_t k = 0; k < own_entries.size(); ++k) {
    if (used[k]) continue;
    out.force_insert(own_entries[k].first, own_entries[k].second);
    if (own_entries[k].first.IsScalar()) {
      const std::string p = child(path, own_entries[k].first.Scalar());
      keep_origins(own_tree, p, origin_in(own_tree, p, own_origin), origins);
    }
  }
  return out;
}

SceneTree resolve(YAML::Node root, const Origin& file, std::deque<Origin>& origins, const SceneParser& parse,
                  std::vector<std::string>& chain) {
  SceneTree own{root, &file, {}};
  if (!root.IsMap()) return own;
  const YAML::Node named = std::as_const(root)[kExtendsKey];
  if (!named) return own;
  const auto fail = [&](const std::string& message) { fail_at(file, named.Mark(), false, "extends: " + message); };
  if (!named.IsScalar() || named.Scalar().empty())
    fail("expected the path of the base scene file, relative to this one, e.g. '../jackson_green_2006.yaml'");
  fs::path base_path(named.Scalar());
  if (base_path.is_relative() && file.is_file) base_path = (fs::path(file.name).parent_path() / base_path).lexically_normal();
  std::error_code error;
  if (!fs::is_regular_file(base_path, error))
    fail(fmt::format("cannot read the base scene '{}': no such file", base_path.string()));
  const std::string canonical = fs::weakly_canonical(base_path, error).string();
  for (const std::string& seen : chain)
    if (seen == canonical)
      fail(fmt::format("the base scene '{}' extends, through its own bases, the scene that extends it; "
                       "a chain of bases must end in a scene without 'extends'",
                       base_path.string()));
  std::ifstream in(base_path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) fail(fmt::format("cannot read the base scene '{}'", base_path.string()));
  Origin& base = origins.emplace_back(Origin{.name = base_path.string(), .is_file = true, .lines = split_lines(text.str())});
  chain.push_back(canonical);
  const SceneTree base_tree = resolve(parse(base, text.str()), base, origins, parse, chain);
  chain.pop_back();
  if (!base_tree.root.IsMap())
    fail(fmt::format("the base scene '{}' is not a map of sections (effects, geometry, ...)", base_path.string()));
  root.remove(kExtendsKey);
  SceneTree out{YAML::Node(), &file, {}};
  out.root = merge(base_tree.root, base_tree, root, own, "", base_tree.origin, &file, out.origins);
  return out;
}

}  // namespace

SceneTree resolve_extends(YAML::Node root, const Origin& file, std::deque<Origin>& origins, const SceneParser& parse) {
  std::vector<std::string> chain;
  std::error_code error;
  if (file.is_file) chain.push_back(fs::weakly_canonical(file.name, error).string());
  return resolve(root, file, origins, parse, chain);
}

}  // namespace twb::scene_io
