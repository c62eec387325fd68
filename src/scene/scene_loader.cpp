#include "twb/scene/scene_loader.h"

#include <cerrno>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "scene_node.h"
#include "scene_extends.h"
#include "scene_overrides.h"
#include "scene_sections.h"
#include "scene_source.h"
#include "yaml_documents.h"
#include "twb/input_error.h"

namespace twb {
namespace {

std::string read_file(const std::string& path) {
  if (std::filesystem::is_directory(path))
    throw InputError(path, 0, 0, fmt::format("cannot read the scene file '{}': it is a directory", path), "");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, 0, 0,
                     fmt::format("cannot open the scene file '{}': {}", path, std::strerror(errno)), "");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string line_at(const scene_io::Origin& file, int line) {
  return line >= 0 && static_cast<std::size_t>(line) < file.lines.size()
             ? file.lines[static_cast<std::size_t>(line)]
             : std::string();
}

YAML::Node parse_yaml(const scene_io::Origin& file, const std::string& text) {
  scene_io::YamlDocuments documents;
  try {
    documents = scene_io::read_documents(text);
  } catch (const YAML::Exception& error) {
    const int line = std::max(error.mark.line, 0);
    throw InputError(file.name, line + 1, std::max(error.mark.column, 0) + 1,
                     fmt::format("YAML syntax error: {}", error.msg), line_at(file, line));
  }
  if (documents.count > 1) {
    // A second document would be ignored silently: most likely a stray '---'.
    const int line = std::max(documents.second.line, 0);
    throw InputError(file.name, line + 1, std::max(documents.second.column, 0) + 1,
                     fmt::format("the file holds {} YAML documents; a scene is one document "
                                 "(remove the '---' separators)",
                                 documents.count),
                     line_at(file, line));
  }
  return documents.first;
}

// A scene's text as its readers see it: its bases laid under it, the overrides over it,
// every value's origin kept (the Origins live as long as the provenance pointing at them).
struct SceneText {
  scene_io::Origin file;
  std::deque<scene_io::Origin> bases, override_origins;
  scene_io::Provenance provenance{&file};
  YAML::Node root;

  SceneText(const std::string& text, const std::string& name, const std::vector<std::string>& overrides)
      : file{.name = name, .is_file = true, .lines = scene_io::split_lines(text)} {
    const scene_io::SceneTree tree = scene_io::resolve_extends(parse_yaml(file, text), file, bases, parse_yaml);
    root = tree.root;
    for (const auto& [path, origin] : tree.origins) provenance.assign(path, origin);
    scene_io::apply_overrides(root, overrides, override_origins, provenance);
  }
  SceneText(const SceneText&) = delete;
  SceneText& operator=(const SceneText&) = delete;
};

// Every value of the tree (a scalar, a list, an empty value) with the file and line that
// wrote it, or the override.
void collect_sources(const YAML::Node& node, const std::string& path, const scene_io::Origin* origin,
                     const scene_io::Provenance& provenance, std::vector<ValueSource>& out) {
  if (node.IsMap()) {
    for (const auto& entry : node) {
      if (!entry.first.IsScalar()) continue;
      const std::string child = path.empty() ? entry.first.Scalar() : path + "." + entry.first.Scalar();
      collect_sources(entry.second, child, provenance.origin_of(child, origin), provenance, out);
    }
    return;
  }
  const int line = origin->is_file && node.Mark().line >= 0 ? node.Mark().line + 1 : 0;
  out.push_back({path, origin->name, line});
}

}  // namespace

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return load_scene_text(read_file(path), path, overrides);
}

std::vector<ValueSource> scene_value_sources(const std::string& path, const std::vector<std::string>& overrides) {
  const SceneText scene(read_file(path), path, overrides);
  std::vector<ValueSource> out;
  collect_sources(scene.root, "", &scene.file, scene.provenance, out);
  return out;
}

Scene load_scene_text(const std::string& text, const std::string& name,
                      const std::vector<std::string>& overrides) {
  const SceneText source(text, name, overrides);
  // An empty document has no mark; errors about it still point at the file's first line.
  const YAML::Mark root_mark = source.root.Mark().line >= 0 ? source.root.Mark() : YAML::Mark();
  Scene scene = scene_io::read_scene(scene_io::Node(source.root, "", &source.file, root_mark, &source.provenance));
  scene.source = name;
  return scene;
}

}  // namespace twb
