// What to compute and how finely: the discretisation (mesh), the nonlinear solver's
// stopping rules (solver), the study to run, and where results go (output).
#include <fmt/format.h>

#include "scene_names.h"
#include "scene_sections.h"

namespace twb::scene_io {
namespace {

void read_mesh(const MapReader& scene, Scene& out) {
  const MapReader mesh = scene.map("mesh", {"radial_nodes", "circumferential_nodes", "contact_quadrature"});
  MeshSettings& m = out.mesh;
  m.radial_nodes = mesh.integer("radial_nodes", 3, m.radial_nodes,
                                "both edges plus at least one interior node");
  m.circumferential_nodes = mesh.integer("circumferential_nodes", 8, m.circumferential_nodes,
                                         "enough to resolve the converging wedge around the circle");
  m.contact_quadrature = mesh.integer("contact_quadrature", 1, m.contact_quadrature);
}

void read_solver(const MapReader& scene, Scene& out) {
  const MapReader solver = scene.map(
      "solver", {"residual_tolerance", "step_tolerance", "max_iterations", "cold_start_film"});
  SolverSettings& s = out.solver;
  s.residual_tolerance =
      solver.quantity("residual_tolerance", si::dimensionless, positive, s.residual_tolerance);
  s.step_tolerance = solver.quantity("step_tolerance", si::dimensionless, positive, s.step_tolerance);
  s.max_iterations = solver.integer("max_iterations", 1, s.max_iterations);
  s.cold_start_film = solver.quantity("cold_start_film", si::dimensionless, positive, s.cold_start_film);
}

void read_study(const MapReader& scene, Scene& out) {
  const MapReader study = scene.map("study", {"type", "load_start", "load_end", "load_steps", "speeds"});
  Study& s = out.study;
  s.type = read_choice(study, "type", kStudyTypes, s.type);
  switch (s.type) {
    case StudyType::point:
      study.restrict_to({"type"}, "with type: point");
      break;
    case StudyType::transient:
      study.restrict_to({"type"}, "with type: transient");
      break;
    case StudyType::load_sweep: {
      study.restrict_to({"type", "load_start", "load_end", "load_steps"}, "with type: load_sweep");
      s.load_start = study.quantity("load_start", si::force, positive);
      s.load_end = study.quantity("load_end", si::force, positive);
      if (s.load_end <= s.load_start) {
        const Node node = study.get("load_end", "");
        node.fail(fmt::format("{}: '{}' must be greater than load_start '{}'", node.path(),
                              node.yaml().Scalar(), study.get("load_start", "").yaml().Scalar()));
      }
      s.load_steps = study.get("load_steps", "a whole number >= 2")
                         .integer(2, "the number of loads, both ends included");
      break;
    }
    case StudyType::distress_map: {
      study.restrict_to({"type", "speeds"}, "with type: distress_map");
      const Node speeds = study.get("speeds", "a list of speeds, e.g. [136 rad/s, 545 rad/s]");
      const std::vector<Node> items = speeds.list("speeds, e.g. [136 rad/s, 545 rad/s]");
      if (items.empty())
        speeds.fail(fmt::format("{}: the list is empty; give at least one speed, e.g. "
                                "[136 rad/s, 545 rad/s]",
                                speeds.path()));
      for (const Node& speed : items) s.speeds.push_back(speed.quantity(si::angular_speed, non_negative));
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
  read_solver(scene, out);
  read_study(scene, out);
  read_output(scene, out);
}

}  // namespace twb::scene_io
