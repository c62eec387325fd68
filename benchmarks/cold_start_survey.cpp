// The paper's 36 cold starts (speeds 136, 545, 953, 1367 rad/s × loads 100, 300, …,
// 1700 N) from the paper's cold start: per state the strategy that reached it, the
// iterations, Jacobians, residuals and wall time, and their totals. The solver's
// globalization is tuned on this survey, so its changes are judged on all 36 states,
// not on the three the benchmark times.
//
//   ./build/benchmarks/cold_start_survey [options] [states.bin [reference.bin]]
//
// With a file name, the converged states are written there; with a second, they are
// compared with that earlier survey's, unknown by unknown (largest difference relative
// to the unknown's largest magnitude over the state).
//
// Options (the thermal deformation's cold start, steady_solver.h):
//   --deformation=free|constrained   the scene with the thermal_deformation effect
//   --no-homotopy                    its cold start by pseudo-time on the deformed film alone
//   --loads=100,150,300              other loads (N) than 100, 300, ..., 1700
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "mesh_option.h"
#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "study/searches/steady_solver.h"

int main(int argc, char** argv) {
  twb::Scene paper = twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml");
  bool homotopy = true;
  std::vector<double> loads;
  for (double load = 100.0; load <= 1700.0; load += 200.0) loads.push_back(load);
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--deformation=", 0) == 0) {
      const std::string faces = arg.substr(14);
      if (faces != "free" && faces != "constrained") {
        fmt::print(stderr, "cold_start_survey: --deformation is free or constrained, not '{}'\n", faces);
        return 2;
      }
      paper.effects.thermal_deformation = true;
      paper.effects.face_expansion = faces == "constrained" ? twb::FaceExpansion::constrained : twb::FaceExpansion::free;
    } else if (arg == "--no-homotopy") {
      homotopy = false;
    } else if (arg.rfind("--loads=", 0) == 0) {
      loads.clear();
      for (const std::string& load : twb::bench::split_list(arg.substr(8))) loads.push_back(std::stod(load));
    } else {
      files.push_back(arg);
    }
  }
  std::ofstream out;
  if (!files.empty()) out.open(files[0], std::ios::binary);
  std::ifstream ref;
  if (files.size() > 1) ref.open(files[1], std::ios::binary);
  long iterations = 0, jacobians = 0, residuals = 0, failures = 0;
  double wall = 0.0, worst = 0.0;
  for (double speed : {136.0, 545.0, 953.0, 1367.0}) {
    for (const double load : loads) {
      twb::Scene s = paper;
      s.operating.speed = speed;
      s.operating.load = load;
      twb::BearingModel model(s);
      twb::SteadySolver solver(model, {});
      solver.set_deformation_homotopy(homotopy);
      std::vector<double> u;
      const twb::SteadyReport rep = solver.solve_cold(u);
      double difference = 0.0;
      if (ref.is_open()) {
        std::vector<double> v(u.size());
        ref.read(reinterpret_cast<char*>(v.data()), std::streamsize(v.size() * sizeof(double)));
        double scale = 0.0;
        for (double x : v) scale = std::max(scale, std::abs(x));
        for (std::size_t k = 0; k < u.size(); ++k) difference = std::max(difference, std::abs(u[k] - v[k]) / scale);
        worst = std::max(worst, difference);
      }
      if (out.is_open()) out.write(reinterpret_cast<const char*>(u.data()), std::streamsize(u.size() * sizeof(double)));
      const double t_max = rep.converged ? model.describe(u).max_film_temperature - 273.15 : NAN;
      const double t_mean = rep.converged ? model.describe(u).washer_mean_temperature - 273.15 : NAN;
      fmt::print("{:6.0f} rad/s {:6.0f} N  {:20s} {:4d} its {:4d} jac {:4d} res {:7.1f} ms  T_mean {:6.1f} C  T_max {:7.1f} C  {}\n",
                 speed, load, rep.converged ? rep.strategy : "FAILED", rep.iterations, rep.jacobian_evaluations,
                 rep.residual_evaluations, rep.wall_ms, t_mean, t_max,
                 ref.is_open() ? fmt::format("differs {:.2e}", difference) : "");
      iterations += rep.iterations;
      jacobians += rep.jacobian_evaluations;
      residuals += rep.residual_evaluations;
      wall += rep.wall_ms;
      failures += !rep.converged;
    }
  }
  fmt::print("total: {} iterations, {} Jacobians, {} residuals, {:.0f} ms, {} failed", iterations, jacobians, residuals,
             wall, failures);
  if (ref.is_open()) fmt::print(", largest state difference {:.2e}", worst);
  fmt::print("\n");
  return failures == 0 ? 0 : 1;
}
