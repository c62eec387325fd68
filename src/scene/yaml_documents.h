// Reading YAML text as one document, as scene files and override values are, in a way
// that always returns: yaml-cpp 0.7's LoadAll loops forever, allocating, on a token its
// parser cannot start a node with (a stray ',' as in ",\n" or "a: 1\n---\n,": yaml-cpp
// issue 1040), so it is not used.
#pragma once

#include <string>

#include <yaml-cpp/yaml.h>

namespace twb::scene_io {

struct YamlDocuments {
  YAML::Node first;   // null for a text without any document
  int count = 0;      // documents in the text
  YAML::Mark second;  // the root node of the second one, when count > 1
};

// Throws YAML::ParserException for a syntax error, including a token the parser cannot
// read past.
YamlDocuments read_documents(const std::string& text);

}  // namespace twb::scene_io
