// study type distress_map: the failure loads over speeds and map combinations, each
// searched on its own or followed from its neighbour's.
#include <fmt/format.h>

#include "twb/scene/scene_inputs.h"
#include "scene/scene_names.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type",      "speeds",        "load_start",     "load_end",
                                      "parameter", "bracket_width", "error_estimate", "method",
                                      "tolerance", "search_past_failure"};

// study.search_past_failure: a factor of the first failure load (at least 1), or none.
void read_search_bound(const MapReader& study, DistressMapSettings& s) {
  read_number_or_none(study, "search_past_failure",
                      Range{.low = 1.0, .high = 1000.0,
                            .reason = "how far past the first failure load the branch is searched, as a factor of "
                                      "it (e.g. 2), or none"},
                      s.search_past_failure);
}

// A followed map moves its inputs by Newton (physics §16): each axis one continuous
// input, the grid fixed, and no refined meshes' searches for error bars.
void check_followed_axes(const MapReader& study, const DistressMapSettings& s) {
  if (s.error_bars.estimate != ErrorEstimate::none) {
    const Node node = study.get("error_estimate", "");
    node.fail(fmt::format("{}: a followed map (method: follow) gives no error bars; leave error_estimate out or set "
                          "it to none, or search every combination (method: search) for their bars",
                          node.path()));
  }
  const std::vector<MapReader> nodes = axis_nodes_of(study);
  for (std::size_t k = 0; k < s.axes.size() && k < nodes.size(); ++k) {
    const MapAxis& axis = s.axes[k];
    std::string why;
    if (axis.parameter == MapParameter::roughness)
      why = "roughness sets every face's Rq and the summits' statistics at once; give one input by its path (e.g. "
            "surfaces.washer.Rq)";
    else if (axis.parameter == MapParameter::groove_count || axis.parameter == MapParameter::groove_width ||
             (axis.parameter == MapParameter::scene_input && !stepwise_input(axis.path).empty()))
      why = "the grooves' count, width and dam and the lands' inlet fraction are placed on the grid's cells and "
            "lines, so their failure loads change by steps that Newton cannot follow (the depths are continuous)";
    else if (axis.parameter == MapParameter::scene_input && axis.path.starts_with("mesh."))
      why = "the mesh is no input of the bearing";
    if (why.empty()) continue;
    const Node name = nodes[k].get("name", "");
    name.fail(fmt::format("{}: a followed map (method: follow) moves each axis's input continuously; {}; or "
                          "search every combination (method: search)",
                          name.path(), why));
  }
}

void read(const MapReader& study, Scene& out) {
  DistressMapSettings& s = std::get<DistressMapSettings>(out.study.settings);
  read_search_bound(study, s);
  s.map_method = read_choice(study, "method", kMapMethods, s.map_method);
  // Followed failure loads have no refined meshes' searches: no error bars by default.
  if (s.map_method == MapMethod::follow) s.error_bars.estimate = ErrorEstimate::none;
  s.error_bars.estimate = read_choice(study, "error_estimate", kErrorEstimates, s.error_bars.estimate);
  read_tolerance(study, s.error_bars);
  read_speeds(study, s.speeds, out.study.speeds_in_rpm);
  read_load_range(study, s.search.loads, " (distress is searched between them)");
  read_map_axes(study, s.axes, out);
  s.search.bracket_width = read_bracket_width(study, s.search.bracket_width);
  if (s.map_method == MapMethod::follow) check_followed_axes(study, s);
}

void write(SceneText& w, const Study& study) {
  const DistressMapSettings& s = std::get<DistressMapSettings>(study.settings);
  write_load_range(w, s.search.loads);
  write_speeds(w, s.speeds);
  write_axes(w, s.axes, "parameter");
  w.entry(1, "bracket_width", quantity(s.search.bracket_width, "1"));
  if (s.map_method == MapMethod::follow) w.entry(1, "method", "follow");
  write_error_estimate(w, s.error_bars);
  write_tolerance(w, s.error_bars);
  w.entry(1, "search_past_failure",
          s.search_past_failure > 0.0 ? quantity(s.search_past_failure, "1") : std::string("none"));
}

}  // namespace

extern const StudySection kDistressMapKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
