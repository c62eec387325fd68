#include "yaml_documents.h"

#include <sstream>
#include <vector>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

namespace twb::scene_io {
namespace {

// Records where each document and its root node start, and builds no nodes.
class DocumentStarts : public YAML::EventHandler {
 public:
  std::vector<YAML::Mark> documents;
  std::vector<YAML::Mark> roots;

  void OnDocumentStart(const YAML::Mark& mark) override { documents.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string&) override {
    node(mark);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnMapEnd() override {}

 private:
  void node(const YAML::Mark& mark) {
    if (roots.size() < documents.size()) roots.push_back(mark);
  }
};

// The byte at a mark, found by its line and column; those count characters, so after a
// byte order mark or a multibyte character on the same line this may be another byte.
char byte_at(const std::string& text, const YAML::Mark& mark) {
  std::size_t start = 0;
  for (int line = 0; line < mark.line && start != std::string::npos; ++line) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos || mark.column < 0) return '\0';
  const std::size_t at = start + static_cast<std::size_t>(mark.column);
  return at < text.size() ? text[at] : '\0';
}

}  // namespace

YamlDocuments read_documents(const std::string& text) {
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  DocumentStarts starts;
  while (parser.HandleNextDocument(starts)) {
    // Every document takes at least one token; one that took none leaves the parser at
    // the same token for ever.
    const auto& marks = starts.documents;
    if (marks.size() > 1 && marks.back().pos == marks[marks.size() - 2].pos) {
      // A ',' is the token known to do this; anything else is not named, rather than
      // named wrongly.
      throw YAML::ParserException(marks.back(), byte_at(text, marks.back()) == ','
                                                    ? "unexpected ','"
                                                    : "unexpected token where a value should start");
    }
  }
  YamlDocuments documents;
  documents.count = static_cast<int>(starts.documents.size());
  if (documents.count > 1) documents.second = starts.roots.size() > 1 ? starts.roots[1] : starts.documents[1];
  // Load reads the first document only, which the scan above has shown to be readable.
  documents.first = YAML::Load(text);
  return documents;
}

}  // namespace twb::scene_io
