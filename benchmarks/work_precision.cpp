// What accuracy costs: one thermal state of the paper's case (545 rad/s, 150 N, from the
// paper's cold start) on a ladder of meshes, from 5×33 each refined by two in both
// directions up to 65×528 (and the tests' 5×24), and at a ladder of solver tolerances; the CPU time of each solve and the state's
// reported quantities, one CSV row each. scripts/work_precision.py turns it into the
// error-against-time figures and tables of benchmarks/README.md.
//
//   ./build/benchmarks/work_precision OUT.csv [--meshes 5x24,5x33,9x66,17x132,33x264,65x528]
//                                             [--tolerances 1e-4,1e-6,1e-8,1e-10,1e-12]
//   ./build/benchmarks/work_precision OUT.csv --distress [--meshes ...] [--speeds 545,953,1367]
//
// With --distress, each row is W_d at one speed on one mesh instead: the fold of the
// cool branch from 100 N (the distress search's fold-only mode, as the error estimate's
// refined meshes use it: W_d is the fold, and the transients only prove it) and its CPU
// time, at the scene's tolerance.
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mesh_option.h"
#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "study/searches/steady_solver.h"
#include "study/searches/distress_search.h"

namespace {

using twb::bench::split_list;

double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

int distress_rows(const char* path, const std::vector<std::string>& meshes, const std::vector<std::string>& speeds) {
  std::ofstream out(path);
  out << "radial_nodes,circumferential_nodes,unknowns,speed_rad_s,cpu_s,W_d_N\n";
  for (const std::string& mesh : meshes) {
    for (const std::string& speed : speeds) {
      std::vector<std::string> keys{"study={type: point}", "operating.speed=" + speed + " rad/s"};
      for (const std::string& k : twb::bench::mesh_overrides(mesh)) keys.push_back(k);
      const twb::Scene scene =
          twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml", keys);
      twb::BearingModel model(scene);
      twb::DistressSearchSettings settings;
      settings.load_start = 100.0;
      settings.load_end = 400.0;
      settings.fold_only = true;
      const double t0 = cpu_seconds();
      const twb::DistressSearch found = twb::search_distress(model, settings, {});
      const double seconds = cpu_seconds() - t0;
      const std::string w_d = found.row.fold_load ? fmt::format("{:.10g}", *found.row.fold_load) : "";
      out << fmt::format("{},{},{},{},{:.6g},{}\n", scene.mesh.radial_nodes, scene.mesh.circumferential_nodes,
                         model.size(), speed, seconds, w_d);
      out.flush();
      std::cerr << fmt::format("{} at {} rad/s: W_d {} N, {:.3g} s\n", mesh, speed, w_d.empty() ? "none" : w_d,
                               seconds);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: work_precision OUT.csv [--meshes RxC,...] [--tolerances t,...]\n";
    return 2;
  }
  std::vector<std::string> meshes = split_list("5x24,5x33,9x66,17x132,33x264,65x528");
  std::vector<std::string> tolerances = split_list("1e-4,1e-6,1e-8,1e-10,1e-12");
  std::vector<std::string> speeds = split_list("545,953,1367");
  bool distress = false;
  for (int i = 2; i < argc; ++i) {
    const std::string key = argv[i];
    if (key == "--distress") {
      distress = true;
      continue;
    }
    if (i + 1 == argc || (key != "--meshes" && key != "--tolerances" && key != "--speeds")) {
      std::cerr << "work_precision: unknown option or missing value: " << key
                << " (allowed: --meshes LIST, --tolerances LIST, --speeds LIST, --distress)\n";
      return 2;
    }
    (key == "--meshes" ? meshes : key == "--tolerances" ? tolerances : speeds) = split_list(argv[++i]);
  }
  if (distress) return distress_rows(argv[1], meshes, speeds);
  std::ofstream out(argv[1]);
  out << "radial_nodes,circumferential_nodes,unknowns,residual_tolerance,cpu_s,newton_iterations,converged,"
         "f_eff,hmin_over_sigma,T_mean_C,fluid_share\n";
  for (const std::string& mesh : meshes) {
    for (const std::string& tolerance : tolerances) {
      std::vector<std::string> keys{"study={type: point}", "operating.load=150 N",
                                    "solver.residual_tolerance=" + tolerance};
      for (const std::string& k : twb::bench::mesh_overrides(mesh)) keys.push_back(k);
      const twb::Scene scene =
          twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml", keys);
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
