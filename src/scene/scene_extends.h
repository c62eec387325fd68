// `extends: BASE` at the top of a scene file (docs/scenes.md, "Scenes that extend
// scenes"): the base file's tree with the file's own keys laid over it, maps merged key
// by key, lists and scalars replaced; bases may extend bases. Every value keeps the
// origin of the file that wrote it, so that errors point there.
#pragma once

#include <deque>
#include <functional>
#include <map>
#include <string>

#include <yaml-cpp/yaml.h>

#include "scene_source.h"

namespace twb::scene_io {

// A scene's tree with the origins of the values that came from other files than its
// own: path ("geometry.washer") → origin; a path not listed has its parent's.
struct SceneTree {
  YAML::Node root;
  const Origin* origin = nullptr;  // the file itself
  std::map<std::string, const Origin*> origins;
};

// The tree of `file` (already parsed into `root`), its `extends` chain resolved (paths
// relative to each extending file). `origins` receives the bases' Origins (a deque, so
// pointers stay valid). Throws InputError at the `extends` value for an unreadable base
// or a cycle, and for any defect of a base's text in the base.
// `parse` turns a base's text into its tree (the loader's YAML reading, errors located).
using SceneParser = std::function<YAML::Node(const Origin& file, const std::string& text)>;
SceneTree resolve_extends(YAML::Node root, const Origin& file, std::deque<Origin>& origins, const SceneParser& parse);

// The top key that names the base.
inline constexpr const char* kExtendsKey = "extends";
// The tag of a map that replaces the base's instead of merging with it
// (e.g. `study: !replace {type: point}`).
inline constexpr const char* kReplaceTag = "!replace";

}  // namespace twb::scene_io
