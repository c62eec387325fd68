// How cost grows with the mesh: CPU time and peak memory of one steady state (545 rad/s,
// 150 N, from the cold start) and of one W_d (545 rad/s, the fold of the cool branch
// from 100 N, as work_precision --distress) against the number of unknowns, with the
// exponent of a least-squares fit of log time against log unknowns. Each solve runs in
// its own child process, so that its peak resident memory (getrusage of the child) is
// its own. Rows as CSV on stdout, the fits on stderr; exit status 1 when a solve failed.
// --distress-meshes none leaves W_d out.
//
//   ./build/benchmarks/growth [--meshes 5x24,9x66,17x132,33x264,65x528] [--distress-meshes ...]
//                             [--repetitions 3] [--no-sequence]
//
// --no-sequence solves every cold start by pseudo-time on the mesh itself, as before
// the mesh sequence (steady_solver.h), for the comparison in benchmarks/README.md.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mesh_option.h"
#include "model/bearing_model.h"
#include "twb/scene/scene_loader.h"
#include "solver/sparse_lu.h"
#include "study/searches/steady_solver.h"
#include "study/searches/distress_search.h"

namespace {

using twb::bench::split_list;

struct Measured {
  long unknowns = 0;
  double cpu_s = 0, peak_mb = 0;
  long newton_iterations = 0, factorizations = 0;
  bool ok = false;
};

// One solve in the calling (child) process: unknowns, CPU seconds, Newton iterations,
// KLU factorizations, success, as one line for the parent.
std::string solve_once(const std::string& mesh, bool distress, bool sequence) {
  std::vector<std::string> keys{"study={type: point}", "operating.speed=545 rad/s", "operating.load=150 N"};
  for (const std::string& k : twb::bench::mesh_overrides(mesh)) keys.push_back(k);
  const twb::Scene scene = twb::load_scene(std::string(TWB_SOURCE_DIR) + "/configs/jackson_green_2006.yaml", keys);
  // The model's construction (its pattern, its contact tables) is not the solve's.
  twb::BearingModel model(scene);
  const double t0 = double(std::clock()) / CLOCKS_PER_SEC;
  const twb::SparseLu::Counts before = twb::SparseLu::thread_counts();
  long iterations = 0;
  bool ok = false;
  if (distress) {
    twb::DistressSearchSettings settings;
    settings.load_start = 100.0;
    settings.load_end = 400.0;
    settings.fold_only = true;
    ok = twb::search_distress(model, settings, {}).row.fold_load.has_value();
  } else {
    twb::NewtonSettings newton;
    newton.residual_tolerance = scene.solver.residual_tolerance;
    twb::SteadySolver solver(model, newton);
    solver.set_mesh_sequence(sequence);
    std::vector<double> u;
    const twb::SteadyReport rep = solver.solve_cold(u);
    iterations = rep.iterations;
    ok = rep.converged;
  }
  const double cpu = double(std::clock()) / CLOCKS_PER_SEC - t0;
  return fmt::format("{} {} {} {} {}", model.size(), cpu, iterations,
                     twb::SparseLu::thread_counts().factored_since(before), ok ? 1 : 0);
}

Measured measure(const std::string& mesh, bool distress, bool sequence) {
  int pipe_fd[2];
  if (pipe(pipe_fd) != 0) throw std::runtime_error("pipe failed");
  const pid_t child = fork();
  if (child == 0) {
    close(pipe_fd[0]);
    const std::string line = solve_once(mesh, distress, sequence);
    if (write(pipe_fd[1], line.data(), line.size()) < 0) _exit(1);
    _exit(0);
  }
  close(pipe_fd[1]);
  std::string line;
  char buffer[256];
  for (ssize_t n; (n = read(pipe_fd[0], buffer, sizeof buffer)) > 0;) line.append(buffer, std::size_t(n));
  close(pipe_fd[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  Measured m;
  std::istringstream in(line);
  int ok = 0;
  in >> m.unknowns >> m.cpu_s >> m.newton_iterations >> m.factorizations >> ok;
  m.ok = in && ok == 1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  m.peak_mb = double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
  return m;
}

// Slope of the least-squares line through (log x, log y).
double fitted_exponent(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = double(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double lx = std::log(x[k]), ly = std::log(y[k]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// False when a solve failed.
bool run(const char* what, const std::vector<std::string>& meshes, bool distress, bool sequence, int repetitions) {
  std::vector<double> unknowns, seconds, memory;
  bool all = true;
  for (const std::string& mesh : meshes) {
    std::vector<Measured> runs;
    for (int r = 0; r < repetitions; ++r) runs.push_back(measure(mesh, distress, sequence));
    std::sort(runs.begin(), runs.end(), [](const Measured& a, const Measured& b) { return a.cpu_s < b.cpu_s; });
    const Measured& median = runs[runs.size() / 2];
    std::cout << fmt::format("{},{},{},{:.4g},{:.1f},{},{},{}\n", what, mesh, median.unknowns, median.cpu_s,
                             median.peak_mb, median.newton_iterations, median.factorizations, median.ok ? 1 : 0)
              << std::flush;
    all = all && median.ok;
    if (!median.ok) continue;
    unknowns.push_back(double(median.unknowns));
    seconds.push_back(median.cpu_s);
    memory.push_back(median.peak_mb);
  }
  if (unknowns.size() < 2) return all;
  std::cerr << fmt::format("{}: time ~ n^{:.2f}, peak memory ~ n^{:.2f} (least squares over {} meshes)", what,
                           fitted_exponent(unknowns, seconds), fitted_exponent(unknowns, memory), unknowns.size());
  // The local exponents between neighbouring meshes show where the growth bends.
  std::cerr << "; local:";
  for (std::size_t k = 1; k < unknowns.size(); ++k)
    std::cerr << fmt::format(" {:.2f}", std::log(seconds[k] / seconds[k - 1]) / std::log(unknowns[k] / unknowns[k - 1]));
  std::cerr << "\n";
  return all;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> meshes = split_list("5x24,9x66,17x132,33x264,65x528");
  std::vector<std::string> distress_meshes = split_list("5x24,9x66,17x132,33x264");
  int repetitions = 3;
  bool sequence = true;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (key == "--no-sequence") {
      sequence = false;
    } else if (i + 1 < argc && key == "--meshes") {
      meshes = split_list(argv[++i]);
    } else if (i + 1 < argc && key == "--distress-meshes") {
      distress_meshes = split_list(argv[++i]);
    } else if (i + 1 < argc && key == "--repetitions") {
      repetitions = std::max(1, std::atoi(argv[++i]));
    } else {
      std::cerr << "growth: unknown option or missing value: " << key
                << " (allowed: --meshes LIST, --distress-meshes LIST, --repetitions N, --no-sequence)\n";
      return 2;
    }
  }
  std::cout << "solve,mesh,unknowns,cpu_s,peak_memory_MB,newton_iterations,factorizations,converged\n";
  bool ok = run("steady state", meshes, false, sequence, repetitions);
  if (!distress_meshes.empty() && distress_meshes.front() != "none")
    ok = run("W_d", distress_meshes, true, sequence, repetitions) && ok;
  return ok ? 0 : 1;
}
