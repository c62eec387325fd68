// study type sensitivity: the state's derivatives against the scene's inputs, and the
// failure load's where a load range is given.
#include <fmt/format.h>

#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type", "parameters", "load_start", "load_end", "bracket_width"};

void read(const MapReader& study, Scene& out) {
  SensitivitySettings& s = std::get<SensitivitySettings>(out.study.settings);
  // The state at the operating point, and with a load range the failure load there.
  if (study.has("load_start") || study.has("load_end"))
    read_load_range(study, s.search.loads, " (distress is searched between them)");
  s.search.bracket_width = read_bracket_width(study, s.search.bracket_width);
  if (study.has("parameters")) {
    const Node list = study.get("parameters", "");
    for (const Node& item : list.list("scene paths of inputs, e.g. [geometry.gear.tilt, surfaces.washer.Rq]"))
      s.parameters.push_back(item.scalar("the scene path of an input, e.g. geometry.gear.tilt"));
    if (s.parameters.empty()) list.fail(fmt::format("{}: an empty list; leave the key out to differentiate against "
                                                    "every input the scene file writes", list.path()));
  }
}

void write(SceneText& w, const Study& study) {
  const SensitivitySettings& s = std::get<SensitivitySettings>(study.settings);
  if (s.search.loads.end != 0.0) write_load_range(w, s.search.loads);
  w.entry(1, "bracket_width", quantity(s.search.bracket_width, "1"));
  std::string paths;
  for (const std::string& p : s.parameters) paths += (paths.empty() ? "" : ", ") + p;
  if (!paths.empty()) w.entry(1, "parameters", fmt::format("[{}]", paths));
}

}  // namespace

extern const StudySection kSensitivityKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
