// What to compute and how finely: the discretisation (mesh), the nonlinear solver's
// stopping rules (solver), the study to run, and where results go (output).
#include <algorithm>
#include <cctype>
#include <optional>

#include <fmt/format.h>

#include "twb/scene/scene_inputs.h"

#include "scene_names.h"
#include "physical_bounds.h"
#include "scene_sections.h"

namespace twb::scene_io {
namespace {

void read_mesh(const MapReader& scene, Scene& out) {
  const MapReader mesh =
      scene.map("mesh", {"radial_nodes", "circumferential_nodes", "contact_quadrature", "flat_contact_quadrature",
                         "max_refinements"});
  MeshSettings& m = out.mesh;
  m.radial_nodes = mesh.integer("radial_nodes", 3, bounds::kMostRadialNodes, m.radial_nodes,
                                "both edges plus at least one interior node; finer exceeds any machine's memory");
  m.circumferential_nodes =
      mesh.integer("circumferential_nodes", 8, bounds::kMostCircumferentialNodes, m.circumferential_nodes,
                   "enough to resolve the converging wedge around the circle; finer exceeds any machine's memory");
  m.contact_quadrature = mesh.integer("contact_quadrature", 1, bounds::kMostQuadraturePoints,
                                      m.contact_quadrature, "Gauss points per direction");
  m.flat_contact_quadrature = mesh.integer("flat_contact_quadrature", 1, bounds::kMostQuadraturePoints,
                                           m.flat_contact_quadrature, "Gauss points per direction");
  // Each refinement multiplies the unknowns by about four and the cost by about six; five
  // take the paper's 9 x 66 to 289 x 2112, past any machine's memory for a fold.
  m.max_refinements = mesh.integer("max_refinements", 1, 5, m.max_refinements,
                                   "how many times a study's tolerance may refine the scene's mesh by two");
}

void read_solver(const MapReader& scene, Scene& out) {
  const MapReader solver = scene.map("solver", {"method", "residual_tolerance", "step_tolerance", "max_iterations",
                                                "cold_start_film", "over_relaxation"});
  SolverSettings& s = out.solver;
  s.method = read_choice(solver, "method", kSolverMethods, s.method);
  // The paper's scheme solves one state from the paper's cold start; continuation,
  // transients and distress searches are twb's own.
  if (s.method == SolverMethod::paper && out.study.type != StudyType::point) {
    const Node method = solver.get("method", "");
    method.fail(fmt::format("{}: 'paper' solves one operating point (study type: point); a {} study needs "
                            "method: newton",
                            method.path(), kStudyTypes.names[kStudyTypes.index(out.study.type)]));
  }
  // The baseline is the paper's scheme on the paper's rigid model; its segregated heat
  // loop is not built for the films' shapes moving with the temperatures.
  if (s.method == SolverMethod::paper && out.effects.thermal_deformation) {
    const Node method = solver.get("method", "");
    method.fail(fmt::format("{}: 'paper' solves the paper's rigid bearing; with the effect thermal_deformation "
                            "use method: newton",
                            method.path()));
  }
  // ... and its projected SOR is the Reynolds condition's.
  if (s.method == SolverMethod::paper && out.effects.cavitation == CavitationModel::jfo) {
    const Node method = solver.get("method", "");
    method.fail(fmt::format("{}: 'paper' solves the Reynolds cavitation condition (projected SOR); with "
                            "cavitation: jfo use method: newton",
                            method.path()));
  }
  if (s.method != SolverMethod::paper && solver.has("over_relaxation")) {
    const Node node = solver.get("over_relaxation", "");
    node.fail(fmt::format("{}: the over-relaxation factor belongs to the paper's scheme; it applies with method: "
                          "paper",
                          node.path()));
  }
  s.over_relaxation = solver.quantity("over_relaxation", si::dimensionless,
                                      Range{.low = 0.0, .low_open = true, .high = 2.0, .high_open = true,
                                            .reason = "SOR converges for 0 < ω < 2"},
                                      s.over_relaxation);
  s.residual_tolerance =
      solver.quantity("residual_tolerance", si::dimensionless, bounds::tolerance, s.residual_tolerance);
  s.step_tolerance = solver.quantity("step_tolerance", si::dimensionless, bounds::tolerance, s.step_tolerance);
  s.max_iterations = solver.integer("max_iterations", 1, bounds::kMostIterations, s.max_iterations,
                                    "Newton iterations per solve");
  s.cold_start_film = solver.quantity("cold_start_film", si::dimensionless, bounds::cold_start_film, s.cold_start_film);
}

void read_load_range(const MapReader& study, Study& s, std::string_view end_relation) {
  s.load_start = study.quantity("load_start", si::force, bounds::load);
  s.load_end = study.quantity("load_end", si::force, bounds::load);
  if (s.load_end <= s.load_start) {
    const Node node = study.get("load_end", "");
    node.fail(fmt::format("{}: '{}' must be greater than load_start '{}'{}", node.path(), node.yaml().Scalar(),
                          study.get("load_start", "").yaml().Scalar(), end_relation));
  }
}

// A dimensionless study key that is a number in `range` or `none` (0), left at `value`
// where absent.
void read_number_or_none(const MapReader& study, std::string_view key, const Range& range, double& value) {
  if (!study.has(key)) return;
  const Node node = study.get(key, "");
  value = node.yaml().IsScalar() && node.yaml().Scalar() == "none" ? 0.0
                                                                  : study.quantity(key, si::dimensionless, range);
}

// study.tolerance: a relative accuracy ("1 %", 0.01) or none; refused beside
// error_estimate: none, which asks for no refined mesh at all.
void read_tolerance(const MapReader& study, Study& s) {
  if (study.has("tolerance") && s.error_estimate == ErrorEstimate::none) {
    const Node node = study.get("tolerance", "");
    node.fail(fmt::format("{}: a tolerance refines the mesh until each failure load's error bar meets it, and "
                          "error_estimate: none asks for no error bar; leave one of them out",
                          node.path()));
  }
  read_number_or_none(study, "tolerance",
                      Range{.low = 0.0, .low_open = true, .high = 0.5,
                            .reason = "the relative accuracy wanted of each failure load, e.g. '1 %' or 0.01, or none"},
                      s.tolerance);
}

// study.search_past_failure: a factor of the first failure load (at least 1), or none.
void read_search_bound(const MapReader& study, Study& s) {
  read_number_or_none(study, "search_past_failure",
                      Range{.low = 1.0, .high = 1000.0,
                            .reason = "how far past the first failure load the branch is searched, as a factor of "
                                      "it (e.g. 2), or none"},
                      s.search_past_failure);
}

double read_bracket_width(const MapReader& study, double fallback) {
  return study.quantity("bracket_width", si::dimensionless,
                        Range{.low = 0.0, .low_open = true, .high = 0.1,
                              .reason = "the relative width of the distress bracket, e.g. 0.002"},
                        fallback);
}

// One axis: `{name: friction_coefficient, values: [0.05, 0.1]}`, or an input's scene path
// for a name, whose values are read once every input is known (check_input_axis).
MapAxis read_map_axis(const MapReader& p, const Scene& scene) {
  MapAxis axis;
  const Node name = p.get("name", "friction_coefficient, gear_tilt, roughness, groove_count, groove_width, "
                                  "groove_depth, or an input's scene path such as geometry.gear.tilt");
  // A scene path has a dot; no named parameter does.
  if (name.yaml().IsScalar() && name.yaml().Scalar().find('.') != std::string::npos) {
    axis.parameter = MapParameter::scene_input;
    axis.path = name.yaml().Scalar();
    const Node values = p.get("values", "a list of values, e.g. [1 mrad, 2 mrad]");
    if (values.list("a list of values, e.g. [1 mrad, 2 mrad]").empty())
      values.fail(fmt::format("{}: the list is empty; give at least one value", values.path()));
    return axis;
  }
  axis.parameter = kMapParameters.values[name.choice(kMapParameters.names)];
  const Node values = p.get("values", "a list of values, e.g. [0.05, 0.1, 0.2]");
  const std::vector<Node> items = values.list("a list of values, e.g. [0.05, 0.1, 0.2]");
  if (items.empty())
    values.fail(fmt::format("{}: the list is empty; give at least one value", values.path()));
  // A groove's values are checked against the grooves once those are read
  // (check_groove_parameter).
  for (const Node& item : items) {
    switch (axis.parameter) {
      case MapParameter::friction_coefficient:
        axis.values.push_back(item.quantity(si::dimensionless, bounds::friction_coefficient));
        break;
      case MapParameter::gear_tilt:
        axis.values.push_back(item.quantity(si::angle, bounds::tilt));
        break;
      case MapParameter::roughness:
        axis.values.push_back(item.quantity(si::length, bounds::roughness));
        break;
      case MapParameter::groove_count:
        axis.values.push_back(item.integer(1, 360, "grooves round the face"));
        break;
      case MapParameter::groove_width:
        axis.values.push_back(groove_angle(item, 0.5 * (scene.washer.inner_radius + scene.washer.outer_radius)));
        break;
      case MapParameter::groove_depth:
        axis.values.push_back(item.quantity(si::length, bounds::groove_depth));
        break;
      case MapParameter::none:
      case MapParameter::scene_input:
        break;
    }
  }
  if (axis.parameter == MapParameter::friction_coefficient && scene.friction.law != FrictionLaw::constant)
    name.fail(fmt::format("{}: friction_coefficient varies the constant friction law's coefficient; "
                          "set friction.law: constant",
                          name.path()));
  return axis;
}

// The scene path (or, for the roughness, every path under it) a named parameter sets:
// a grid may not vary one input twice, by its name and by its path.
std::string_view set_by(MapParameter p) {
  switch (p) {
    case MapParameter::friction_coefficient: return "friction.coefficient";
    case MapParameter::gear_tilt: return "geometry.gear.tilt";
    case MapParameter::roughness: return "surfaces.";
    case MapParameter::groove_count: return "geometry.washer.grooves.count";
    case MapParameter::groove_width: return "geometry.washer.grooves.width";
    case MapParameter::groove_depth: return "geometry.washer.grooves.depth";
    case MapParameter::none:
    case MapParameter::scene_input: break;
  }
  return {};
}

bool same_input(const MapAxis& a, const MapAxis& b) {
  const bool a_path = a.parameter == MapParameter::scene_input, b_path = b.parameter == MapParameter::scene_input;
  if (a_path && b_path) return a.path == b.path;
  if (!a_path && !b_path) return a.parameter == b.parameter;
  const MapAxis& named = a_path ? b : a;
  const std::string& path = a_path ? a.path : b.path;
  const std::string_view sets = set_by(named.parameter);
  return sets.ends_with('.') ? path.starts_with(sets) : path == sets;
}

// The axes of a distress map or load sweep besides the speed: `parameter: {name: ...,
// values: [...]}`, or a list of such maps, a grid of every combination; a distress
// curve's family: `family: {...}`, one axis.
void read_map_axes(const MapReader& study, Study& s, const Scene& scene, const char* key = "parameter") {
  if (!study.has(key)) return;
  const Node node = study.get(key, "");
  if (!(std::string_view(key) == "parameter" && node.yaml().IsSequence())) {
    s.axes.push_back(read_map_axis(study.map(key, {"name", "values"}), scene));
    return;
  }
  const std::vector<Node> items = node.list("a list of axes, each {name: ..., values: [...]}");
  if (items.empty())
    node.fail(fmt::format("{}: the list is empty; give at least one axis, e.g. [{{name: friction_coefficient, "
                          "values: [0.05, 0.1]}}]",
                          node.path()));
  for (const Node& item : items) {
    const MapReader p(item, {"name", "values"});
    MapAxis axis = read_map_axis(p, scene);
    for (const MapAxis& before : s.axes)
      if (same_input(before, axis)) {
        const Node name = p.get("name", "");
        const bool twice = before.parameter == axis.parameter && before.path == axis.path;
        name.fail(twice ? fmt::format("{}: {} is an axis of this grid already; each axis varies another input",
                                      name.path(), name.yaml().Scalar())
                        : fmt::format("{}: {} varies what the axis {} varies already; each axis varies another input",
                                      name.path(), name.yaml().Scalar(),
                                      before.parameter == MapParameter::scene_input
                                          ? before.path
                                          : std::string(kMapParameters.name(before.parameter))));
      }
    s.axes.push_back(std::move(axis));
  }
}

// Whether a speed was written in revolutions per minute ("3000 rpm", "3 krpm",
// "50 r/min"): what the figures then show (run.json's speed_unit).
bool given_in_rpm(const Node& speed) {
  if (!speed.yaml().IsScalar()) return false;
  std::string text = speed.yaml().Scalar();
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text.ends_with("rpm") || text.ends_with("r/min") || text.ends_with("rev/min");
}

// The speeds of one search each: `speeds: [136 rad/s, 545 rad/s]`.
void read_speeds(const MapReader& study, Study& s) {
  const Node speeds = study.get("speeds", "a list of speeds, e.g. [136 rad/s, 545 rad/s]");
  const std::vector<Node> items = speeds.list("speeds, e.g. [136 rad/s, 545 rad/s]");
  if (items.empty())
    speeds.fail(fmt::format("{}: the list is empty; give at least one speed, e.g. "
                            "[136 rad/s, 545 rad/s]",
                            speeds.path()));
  for (const Node& speed : items) s.speeds.push_back(speed.quantity(si::angular_speed, bounds::speed));
  s.speeds_in_rpm = std::all_of(items.begin(), items.end(), [](const Node& n) { return given_in_rpm(n); });
}

// A load grid (load_sweep, sliding_choice): the range, its number of loads, and the
// speeds, operating.speed when the study names none.
void read_load_grid(const MapReader& study, Scene& out) {
  Study& s = out.study;
  read_load_range(study, s, "");
  s.load_steps = study.get("load_steps", "a whole number in [2, 10000]")
                     .integer(2, 10000, "the number of loads, both ends included");
  if (study.has("speeds"))
    read_speeds(study, s);
  else
    s.speeds = {out.operating.speed};
  s.bracket_width = read_bracket_width(study, s.bracket_width);
}

// distress_curve: `parameter: speed`, `from`, `to` in its unit, the first fold's load
// range optional.
void read_fold_curve(const MapReader& study, Scene& out) {
  Study& s = out.study;
  const Node name =
      study.get("parameter", "speed, friction_coefficient, gear_tilt, ambient_temperature, viscosity_scale or roughness");
  s.curve_parameter = kCurveParameters.values[name.choice(kCurveParameters.names)];
  if (s.curve_parameter == CurveParameter::friction_coefficient && out.friction.law != FrictionLaw::constant)
    name.fail(fmt::format("{}: friction_coefficient varies the constant friction law's coefficient; "
                          "set friction.law: constant",
                          name.path()));
  auto value = [&](const char* key) {
    switch (s.curve_parameter) {
      case CurveParameter::speed:
        return study.quantity(key, si::angular_speed, bounds::speed);
      case CurveParameter::friction_coefficient:
        return study.quantity(key, si::dimensionless, bounds::friction_coefficient);
      case CurveParameter::gear_tilt:
        return study.quantity(key, si::angle, bounds::tilt);
      case CurveParameter::ambient_temperature:
        return study.quantity(key, si::temperature, bounds::roelands_temperature);
      case CurveParameter::viscosity_scale:
        return study.quantity(key, si::dimensionless, bounds::viscosity_scale);
      case CurveParameter::roughness:
        return study.quantity(key, si::length, bounds::roughness);
    }
    return 0.0;
  };
  s.from = value("from");
  s.to = value("to");
  if (s.curve_parameter == CurveParameter::speed)
    s.speeds_in_rpm = given_in_rpm(study.get("from", "")) && given_in_rpm(study.get("to", ""));
  if (s.to == s.from) {
    const Node to = study.get("to", "");
    to.fail(fmt::format("{}: '{}' must differ from 'from': the curve needs a range", to.path(), to.yaml().Scalar()));
  }
  // The first fold is searched between these loads (defaults: a fifth and four times
  // operating.load).
  s.load_start = study.quantity("load_start", si::force, bounds::load, 0.2 * out.operating.load);
  s.load_end = study.quantity("load_end", si::force, bounds::load, 4.0 * out.operating.load);
  if (s.load_end <= s.load_start) {
    const Node node = study.has("load_end") ? study.get("load_end", "") : study.get("load_start", "");
    node.fail(fmt::format("{}: load_end must be greater than load_start (here {:.6g} N and {:.6g} N)", node.path(),
                          s.load_end, s.load_start));
  }
  s.bracket_width = read_bracket_width(study, s.bracket_width);
}

// every_state refines each state of a sweep; a point's one state has its bar with
// richardson, and a distress curve reports folds and crossings, not a sweep's states.
void refuse_every_state(const MapReader& study, const Study& s, const char* type) {
  if (s.error_estimate != ErrorEstimate::every_state) return;
  const Node node = study.get("error_estimate", "");
  node.fail(fmt::format("{}: every_state (an error bar on every state of a sweep) is for load_sweep and "
                        "distress_map; with type: {} use richardson or none",
                        node.path(), type));
}

// The nodes of a study's axes (its parameter's or family's maps, in order).
std::vector<MapReader> axis_nodes_of(const MapReader& study) {
  std::vector<MapReader> out;
  const char* key = study.has("family") ? "family" : "parameter";
  if (!study.has(key)) return out;
  const Node node = study.get(key, "");
  if (node.yaml().IsSequence())
    for (const Node& item : node.list("")) out.emplace_back(item, std::vector<std::string_view>{"name", "values"});
  else if (node.yaml().IsMap())
    out.push_back(study.map(key, {"name", "values"}));
  return out;  // none for a distress curve's own parameter (a name)
}

// A followed map moves its inputs by Newton (physics §16): each axis one continuous
// input, the grid fixed, and no refined meshes' searches for error bars.
void check_followed_axes(const MapReader& study, const Study& s) {
  if (s.error_estimate != ErrorEstimate::none) {
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

void read_study(const MapReader& scene, Scene& out) {
  const MapReader study = scene.map("study", {std::begin(kStudyKeys), std::end(kStudyKeys)});
  Study& s = out.study;
  s.type = read_choice(study, "type", kStudyTypes, s.type);
  // (study.speeds, where given, say again)
  if (const std::optional<Node> speed = scene.map("operating", {std::begin(kOperatingKeys), std::end(kOperatingKeys)}).find("speed"))
    s.speeds_in_rpm = given_in_rpm(*speed);
  switch (s.type) {
    case StudyType::point:
      study.restrict_to({"type", "error_estimate", "tolerance"}, "with type: point");
      s.error_estimate = read_choice(study, "error_estimate", kErrorEstimates, s.error_estimate);
      // A point's bar is the two-mesh estimate unless a tolerance is asked for: to 1 % on
      // every quantity a point would cost many times itself (h_min/σ near the contact
      // converges slowest), and its bar's cost is a few times the point's.
      s.tolerance = 0.0;
      read_tolerance(study, s);
      refuse_every_state(study, s, "point");
      break;
    case StudyType::transient:
      study.restrict_to({"type", "load_start", "load_end", "duration", "bracket_width"}, "with type: transient");
      if (!out.effects.thermal) {
        const Node type = study.get("type", "");
        type.fail(fmt::format("{}: a transient study marches the heat balance in pseudo-time (docs/physics.md "
                              "section 8), so it needs the thermal effect; add 'thermal' to effects",
                              type.path()));
      }
      s.load_start = study.quantity("load_start", si::force, bounds::load);
      s.load_end = study.quantity("load_end", si::force, bounds::load);
      s.duration = study.quantity("duration", si::time, bounds::duration, 0.0);
      break;
    case StudyType::load_sweep:
      study.restrict_to({"type", "load_start", "load_end", "load_steps", "speeds", "parameter", "bracket_width",
                         "error_estimate", "tolerance"},
                        "with type: load_sweep");
      read_load_grid(study, out);
      s.error_estimate = read_choice(study, "error_estimate", kErrorEstimates, s.error_estimate);
      read_tolerance(study, s);
      read_map_axes(study, s, out);
      break;
    case StudyType::sliding_choice:
      study.restrict_to({"type", "load_start", "load_end", "load_steps", "speeds", "bracket_width"},
                        "with type: sliding_choice");
      read_load_grid(study, out);
      break;
    case StudyType::distress_curve:
      study.restrict_to({"type", "parameter", "from", "to", "load_start", "load_end", "bracket_width", "family",
                         "error_estimate", "tolerance"},
                        "with type: distress_curve");
      read_fold_curve(study, out);
      s.error_estimate = read_choice(study, "error_estimate", kErrorEstimates, s.error_estimate);
      read_tolerance(study, s);
      refuse_every_state(study, s, "distress_curve");
      read_map_axes(study, s, out, "family");
      break;
    case StudyType::sensitivity:
      // The state at the operating point, and with a load range the failure load there.
      study.restrict_to({"type", "parameters", "load_start", "load_end", "bracket_width"}, "with type: sensitivity");
      if (study.has("load_start") || study.has("load_end")) read_load_range(study, s, " (distress is searched between them)");
      s.bracket_width = read_bracket_width(study, s.bracket_width);
      if (study.has("parameters")) {
        const Node list = study.get("parameters", "");
        for (const Node& item : list.list("scene paths of inputs, e.g. [geometry.gear.tilt, surfaces.washer.Rq]"))
          s.parameters.push_back(item.scalar("the scene path of an input, e.g. geometry.gear.tilt"));
        if (s.parameters.empty()) list.fail(fmt::format("{}: an empty list; leave the key out to differentiate against "
                                                        "every input the scene file writes", list.path()));
      }
      break;
    case StudyType::reliability: {
      // The inputs' distributions are read once every input is known (read_uncertain_inputs).
      study.restrict_to({"type", "inputs", "load_start", "load_end", "bracket_width", "probabilities", "monte_carlo"},
                        "with type: reliability");
      read_load_range(study, s, " (the failure search at the inputs' medians runs between them)");
      // A sample that does not fail up to load_end must be known to survive the operating load.
      if (!(out.operating.load > s.load_start && out.operating.load < s.load_end)) {
        const Node end = study.get("load_end", "");
        end.fail(fmt::format("{}: the operating load {:.6g} N must lie between load_start and load_end: the "
                             "probability of failure at it needs each failure search to reach past it",
                             end.path(), out.operating.load));
      }
      s.bracket_width = read_bracket_width(study, s.bracket_width);
      study.get("inputs", "a map from input paths to distributions, e.g. {geometry.gear.tilt: {distribution: normal, "
                          "mean: 0.5 mrad, sd: 0.1 mrad}}");
      if (study.has("probabilities")) {
        const Node list = study.get("probabilities", "");
        for (const Node& item : list.list("failure probabilities, e.g. [1e-4, 1e-3, 1e-2]"))
          s.probabilities.push_back(item.quantity(
              si::dimensionless, Range{.low = 0.0, .low_open = true, .high = 1.0, .high_open = true,
                                       .reason = "a probability of failure whose load is wanted, e.g. 1e-3"}));
      }
      const MapReader sampling = study.map("monte_carlo", {"cov", "max_samples", "seed"});
      s.sampling_cov = sampling.quantity(
          "cov", si::dimensionless,
          Range{.low = 0.0, .low_open = true, .high = 1.0, .reason = "the estimate's coefficient of variation, e.g. 0.1"},
          s.sampling_cov);
      s.max_samples = sampling.integer("max_samples", 0, 1000000, s.max_samples, "samples at most; 0: no Monte Carlo check");
      s.seed = sampling.integer("seed", 0, int(s.seed), "the samples' seed");
      break;
    }
    case StudyType::calibration:
      // The data and the fitted inputs are read once every input is known (read_calibration).
      study.restrict_to({"type", "data", "fit", "sd", "max_iterations"}, "with type: calibration");
      study.get("data", "the path of the measurements file (CSV), e.g. rig.csv");
      s.fit_iterations = study.integer("max_iterations", 1, 1000, s.fit_iterations,
                                       "Levenberg-Marquardt iterations before the fit stops unconverged");
      study.get("fit", "a map from input paths to bounds, e.g. {surfaces.washer.Rq: {lower: 0.1 um, upper: 1.5 um}}");
      break;
    case StudyType::duty_cycle:
      // The schedule is read once the operating point is known (read_schedule).
      study.restrict_to({"type", "schedule", "failure_load_at_worst", "relative_tolerance"}, "with type: duty_cycle");
      s.failure_load_at_worst = study.boolean("failure_load_at_worst", s.failure_load_at_worst);
      s.march_tolerance =
          study.quantity("relative_tolerance", si::dimensionless, bounds::march_tolerance, s.march_tolerance);
      if (!out.effects.thermal) {
        const Node type = study.get("type", "");
        type.fail(fmt::format("{}: a duty cycle marches the bodies' heat in time (docs/physics.md section 19), so it "
                              "needs the thermal effect; add 'thermal' to effects",
                              type.path()));
      }
      if (out.effects.hydrodynamics && out.effects.cavitation == CavitationModel::jfo) {
        const Node type = study.get("type", "");
        type.fail(fmt::format("{}: a duty cycle solves the film's squeeze (docs/physics.md section 19) with the "
                              "Reynolds cavitation condition only: the mass-conserving model's film content would "
                              "be a differential unknown held at 1 wherever the film is full (a DAE of index two, "
                              "not solved); use hydrodynamics: {{cavitation: reynolds}}",
                              type.path()));
      }
      break;
    case StudyType::distress_map: {
      study.restrict_to({"type", "speeds", "load_start", "load_end", "parameter", "bracket_width", "error_estimate",
                         "method", "tolerance", "search_past_failure"},
                        "with type: distress_map");
      read_search_bound(study, s);
      s.map_method = read_choice(study, "method", kMapMethods, s.map_method);
      // Followed failure loads have no refined meshes' searches: no error bars by default.
      if (s.map_method == MapMethod::follow) s.error_estimate = ErrorEstimate::none;
      s.error_estimate = read_choice(study, "error_estimate", kErrorEstimates, s.error_estimate);
      read_tolerance(study, s);
      read_speeds(study, s);
      read_load_range(study, s, " (distress is searched between them)");
      read_map_axes(study, s, out);
      s.bracket_width = read_bracket_width(study, s.bracket_width);
      if (s.map_method == MapMethod::follow) check_followed_axes(study, s);
      break;
    }
  }
}

void read_output(const MapReader& scene, Scene& out) {
  const MapReader output = scene.map("output", {"directory", "fields"});
  out.output.directory = output.text("directory", out.output.directory);
  out.output.fields = output.boolean("fields", out.output.fields);
}

}  // namespace

void read_numerics(const MapReader& scene, Scene& out) {
  read_mesh(scene, out);
  read_study(scene, out);
  read_solver(scene, out);  // after the study, which the solver's method must suit
  read_output(scene, out);
}

}  // namespace twb::scene_io

namespace twb::scene_io {

std::vector<MapReader> axis_nodes(const MapReader& scene) {
  if (!scene.has("study")) return {};
  return axis_nodes_of(scene.map("study", {std::begin(kStudyKeys), std::end(kStudyKeys)}));
}

}  // namespace twb::scene_io

namespace twb {

bool next_combination(std::vector<std::size_t>& at, const std::vector<std::size_t>& sizes) {
  std::size_t k = at.size();
  while (k > 0 && ++at[k - 1] == sizes[k - 1]) at[--k] = 0;
  return k > 0;
}

std::string parameter_path(const MapAxis& axis) {
  if (axis.parameter == MapParameter::scene_input) return axis.path;
  const std::string_view path = scene_io::set_by(axis.parameter);
  return path.ends_with('.') ? std::string() : std::string(path);
}

}  // namespace twb
