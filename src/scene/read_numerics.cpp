// What to compute and how finely: the discretisation (mesh), the nonlinear solver's
// stopping rules (solver), the study to run, and where results go (output).
#include <optional>

#include <fmt/format.h>

#include "twb/scene/scene_inputs.h"

#include "scene_names.h"
#include "physical_bounds.h"
#include "scene_sections.h"
#include "studies/study_keys.h"
#include "studies/study_section.h"

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
  if (s.method == SolverMethod::paper && out.study.type() != StudyType::point) {
    const Node method = solver.get("method", "");
    method.fail(fmt::format("{}: 'paper' solves one operating point (study type: point); a {} study needs "
                            "method: newton",
                            method.path(), kStudyTypes.names[kStudyTypes.index(out.study.type())]));
  }
  // The baseline is the paper's scheme on the paper's rigid model; its segregated heat
  // loop is not built for the films' shapes moving with the temperatures.
  if (s.method == SolverMethod::paper && out.effects.thermal_deformation) {
    const Node method = solver.get("method", "");
    method.fail(fmt::format("{}: 'paper' solves the paper's rigid bearing; with the effect thermal_deformation "
                            "use method: newton",
                            method.path()));
  }
  // ... nor for a washer that bends.
  if (s.method == SolverMethod::paper && out.effects.elastic_washer) {
    const Node method = solver.get("method", "");
    method.fail(fmt::format("{}: 'paper' solves the paper's rigid bearing; with the effect elastic_washer use "
                            "method: newton",
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

void read_study(const MapReader& scene, Scene& out) {
  const MapReader study = scene.map("study", {std::begin(kStudyKeys), std::end(kStudyKeys)});
  Study& s = out.study;
  const StudyType type = read_choice(study, "type", kStudyTypes, s.type());
  s.settings = default_settings(type);
  // (study.speeds, where given, say again)
  if (const std::optional<Node> speed = scene.map("operating", {std::begin(kOperatingKeys), std::end(kOperatingKeys)}).find("speed"))
    s.speeds_in_rpm = given_in_rpm(*speed);
  const StudySection& section = study_section(type);
  study.restrict_to({section.keys.begin(), section.keys.end()}, fmt::format("with type: {}", kStudyTypes.name(type)));
  section.read(study, out);
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
