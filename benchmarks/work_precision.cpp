// What accuracy costs: one thermal state of the paper's case (545 rad/s, 150 N, from the
// paper's cold start) on a ladder of meshes, from 5×33 each refined by two in both
// directions up to 65×528 (and the tests' 5×24), and at a ladder of solver tolerances; the CPU time of each solve and the state's
// reported quantities, one CSV row each. scripts/work_precision.py turns it into the
// error-against-time figures and tables of benchmarks/README.md.
//
//   ./build/benchmarks/work_precision OUT.csv [--meshes 5x24,5x33,9x66,17x132,33x264,65x528]
//                                             [--tolerances 1e-4,1e-6,1e-8,1e-10,1e-12]
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "twb/model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "twb/solver/steady_solver.h"

namespace {

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> parts;
  std::stringstream in(list);
  for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
  return parts;
}

double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: work_precision OUT.csv [--meshes RxC,...] [--tolerances t,...]\n";
    return 2;
  }
  std::vector<std::string> meshes = split("5x24,5x33,9x66,17x132,33x264,65x528");
  std::vector<std::string> tolerances = split("1e-4,1e-6,1e-8,1e-10,1e-12");
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--meshes")
      meshes = split(argv[i + 1]);
    else if (key == "--tolerances")
      tolerances = split(argv[i + 1]);
    else {
      std::cerr << "work_precision: unknown option " << key << " (allowed: --meshes, --tolerances)\n";
      return 2;
    }
  }
  std::ofstream out(argv[1]);
  out << "radial_nodes,circumferential_nodes,unknowns,residual_tolerance,cpu_s,newton_iterations,converged,"
         "f_eff,hmin_over_sigma,T_mean_C,fluid_share\n";
  for (const std::string& mesh : meshes) {
    const auto x = mesh.find('x');
    if (x == std::string::npos) {
      std::cerr << "work_precision: a mesh is RxC, e.g. 9x66, not " << mesh << "\n";
      return 2;
    }
    for (const std::string& tolerance : tolerances) {
      const twb::Scene scene = twb::load_scene(
          std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml",
          {"study={type: point}", "operating.load=150 N", "mesh.radial_nodes=" + mesh.substr(0, x),
           "mesh.circumferential_nodes=" + mesh.substr(x + 1), "solver.residual_tolerance=" + tolerance});
      twb::BearingModel model(scene);
      twb::NewtonSettings newton;
      newton.residual_tolerance = scene.solver.residual_tolerance;
      std::vector<double> u;
      const double t0 = cpu_seconds();
      const twb::SteadyReport rep = twb::SteadySolver(model, newton).solve_cold(u);
      const double seconds = cpu_seconds() - t0;
      const twb::BearingState s = model.describe(u);
      out << fmt::format("{},{},{},{},{:.6g},{},{},{:.15g},{:.15g},{:.15g},{:.15g}\n", scene.mesh.radial_nodes,
                         scene.mesh.circumferential_nodes, model.size(), tolerance, seconds, rep.iterations,
                         rep.converged ? 1 : 0, s.f_eff, s.hmin_over_sigma, s.washer_mean_temperature - 273.15,
                         s.fluid_share);
      out.flush();
      std::cerr << fmt::format("{} at {}: {:.3g} s, {} iterations{}\n", mesh, tolerance, seconds, rep.iterations,
                               rep.converged ? "" : " (not converged: " + rep.message + ")");
    }
  }
  return 0;
}
