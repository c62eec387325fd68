// A transmission model's view of a thrust washer: for one washer and oil (a twb scene)
// it asks, at each gear load, for the friction torque, the washer temperature and how
// much load the oil film carries, stepping through the loads so that each state starts
// from the last; then it runs the scene's own study (here: where the film fails).
//
//   washer_points SCENE [LOAD_N ...]
#include <cstdio>
#include <string>
#include <vector>

#include <twb/twb.h>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCENE [LOAD_N ...]\n", argv[0]);
    return 2;
  }
  std::vector<double> loads;
  for (int k = 2; k < argc; ++k) loads.push_back(std::stod(argv[k]));
  if (loads.empty()) loads = {50.0, 100.0, 150.0};

  try {
    // W_d on the scene's mesh alone, without the error bar from the refined mesh: the
    // same override `twb run --set` takes.
    const twb::Scene scene = twb::load_scene(argv[1], {"study.error_estimate=none"});
    twb::Bearing bearing(scene);
    std::printf("twb %s: %ld unknowns\n", twb::version(), bearing.unknown_count());
    for (const twb::UnknownBlock& b : bearing.unknowns())
      std::printf("  %-40s %6lld  (%s)\n", b.name.c_str(), static_cast<long long>(b.size),
                  twb::effect_name(b.effect));

    const double speed = scene.operating.speed;
    std::printf("%8s %10s %10s %10s %8s %6s\n", "load N", "torque Nm", "T_mean C", "hmin/sig", "fluid", "iter");
    for (double load : loads) {
      const twb::SolvedState s = bearing.solve(load, speed);
      std::printf("%8.1f %10.4g %10.2f %10.3f %8.3f %6ld\n", s.state.load, s.state.torque,
                  s.state.washer_mean_temperature - 273.15, s.state.hmin_over_sigma, s.state.fluid_share,
                  s.iterations);
    }

    const twb::StudyOutcome study = bearing.run_study();
    for (const twb::DistressRow& d : study.distress)
      if (d.distress_load)
        std::printf("distress at %.1f rad/s: %.17g N\n", d.speed, *d.distress_load);
      else
        std::printf("distress at %.1f rad/s: none\n", d.speed);
    return study.solver_failed ? 3 : 0;
  } catch (const twb::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const twb::SolverFailure& e) {
    std::fprintf(stderr, "solver failure: %s\n", e.what());
    return 3;
  }
}
