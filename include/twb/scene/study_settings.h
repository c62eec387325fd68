// What a scene's study asks for: the study types and the settings they read from the
// scene's `study` section (docs/scenes.md), in SI units; part of the validated scene
// (scene.h).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace twb {

// sliding_choice: both sliding configurations over a load grid, the one of lower
// friction torque kept (docs/physics.md section 2, the paper's "Component Rotational Speed").
enum class StudyType {
  point, load_sweep, distress_map, transient, sliding_choice, distress_curve, sensitivity, reliability, calibration,
  duty_cycle
};

// The optional second axis of a distress map or load sweep (besides speed).
// roughness: the Rq of every surface (see docs/scenes.md for how the texture scales).
// scene_input: any input of the scene by its path (Study::parameter_path; scene_inputs.h).
enum class MapParameter {
  none, friction_coefficient, gear_tilt, roughness, groove_count, groove_width, groove_depth, scene_input
};

// A parameter of the bearing a fold curve is continued in (study type distress_curve),
// set on a built model without rebuilding it.
// viscosity_scale multiplies the oil's viscosity at every temperature (1: the scene's oil).
// roughness: the Rq of every surface (set_roughness).
enum class CurveParameter { speed, friction_coefficient, gear_tilt, ambient_temperature, viscosity_scale, roughness };

// An uncertain input's distribution (study type reliability, docs/physics.md section 17).
// normal: mean, sd; lognormal: the input's own mean and sd (its logarithm normal);
// uniform: lower, upper; truncated_normal: the normal (mean, sd) cut to [lower, upper].
enum class InputDistribution { normal, lognormal, uniform, truncated_normal };

struct UncertainInput {
  std::string path;  // the input's scene path, e.g. "geometry.gear.tilt"
  std::string unit;  // its SI unit
  InputDistribution distribution = InputDistribution::normal;
  double mean = 0.0, sd = 0.0;        // SI (normal, lognormal, truncated_normal)
  double lower = 0.0, upper = 0.0;    // SI (uniform, truncated_normal)
};

// What a rig measures that a calibration study fits (docs/physics.md section 18): the
// friction torque, the effective friction coefficient, the washer's mean and the film's
// hottest temperature.
enum class MeasuredQuantity { torque, f_eff, T_mean, T_max };
inline constexpr std::size_t kMeasuredQuantities = 4;

// One measured operating point (a row of the calibration's data file).
struct MeasuredPoint {
  double load = 0.0;   // N
  double speed = 0.0;  // rad/s
  double ambient = 0.0;  // K, the oil's (the sump's) at the point; 0: the scene's operating.ambient
  // SI (N m, 1, K), by MeasuredQuantity; NaN where the point does not measure it
  std::array<double, kMeasuredQuantities> values{};
  // Each reading's own standard deviation (SI; a temperature's in K), where the data give
  // one (a `<quantity>_sd` column); NaN elsewhere
  std::array<double, kMeasuredQuantities> sd{std::numeric_limits<double>::quiet_NaN(),
                                             std::numeric_limits<double>::quiet_NaN(),
                                             std::numeric_limits<double>::quiet_NaN(),
                                             std::numeric_limits<double>::quiet_NaN()};
  int line = 0;  // its line in the data file
};

// An input fitted by a calibration study: its scene path and SI unit, where the fit
// starts and the bounds it keeps to (SI).
struct FittedInput {
  std::string path, unit;
  double start = 0.0, lower = 0.0, upper = 0.0;
};

// How a distress search estimates the discretization error of W_d.
enum class ErrorEstimate {
  none,
  richardson,   // the fold again on the mesh refined by two in each direction, extrapolated
  every_state,  // that, and every state of a sweep too (load_sweep, distress_map)
};

// One axis of a map, sweep or curve family: a named parameter or an input by its scene
// path, and its values.
struct MapAxis {
  MapParameter parameter = MapParameter::none;
  std::string path;            // scene_input: the input's path, e.g. "geometry.gear.tilt"
  std::string unit;            // scene_input: its SI unit ("rad"; "1" for a pure number)
  std::vector<double> values;  // SI (dimensionless, rad, m; scene_input: the input's SI unit)
  bool operator==(const MapAxis&) const = default;
};

// How a distress map finds each combination's failure load: a failure search at each,
// or followed by Newton from a neighbour's settled criteria (docs/physics.md section 16).
enum class MapMethod { search, follow };

// A point of a duty cycle's schedule (study type duty_cycle, docs/physics.md section 19):
// the operating point at `time`, piecewise linear between points, held after the last.
struct SchedulePoint {
  double time = 0.0;     // s, strictly increasing along the schedule
  double load = 0.0;     // N
  double speed = 0.0;    // rad/s; negative: the washer turns back
  double ambient = 0.0;  // K
  double tilt = 0.0;     // rad, the gear's imposed tilt (geometry.gear.tilt)
  // Where it was written, for messages: the scene file's or the schedule CSV's path and
  // 1-based line.
  std::string file;
  int line = 0;
};

struct Study {
  StudyType type = StudyType::point;
  // load_sweep, distress_map, sliding_choice: the load range continued over; transient:
  // the load before (load_start) and after (load_end) the step.
  double load_start = 0.0;  // N
  double load_end = 0.0;    // N
  int load_steps = 0;       // load_sweep, sliding_choice: states on the requested grid, ends included
  // load_sweep, distress_map, sliding_choice: the speeds, one search per speed (a load
  // sweep without `speeds` in the file gets operating.speed)
  std::vector<double> speeds;  // rad/s
  // load_sweep, distress_map: the axes besides the speed, each search one combination of
  // their values (a grid: the first axis outermost); distress_curve: its family's axis.
  std::vector<MapAxis> axes;
  // Distress bracket refined by bisection to (high − low)/high <= bracket_width.
  double bracket_width = 0.002;
  // distress_curve: the fold continued in this parameter from `from` to `to` (SI).
  CurveParameter curve_parameter = CurveParameter::speed;
  double from = 0.0, to = 0.0;
  // load_sweep, distress_map: W_d's discretization error (docs/model.md, "Distress on the bearing").
  ErrorEstimate error_estimate = ErrorEstimate::richardson;
  // load_sweep, distress_map: the relative accuracy every failure load is wanted to; the
  // mesh is refined by two until each estimated error is within it (docs/physics.md
  // section 8, "To a requested accuracy"). 0: none (one refinement, a bar of the formal
  // order, as error_estimate alone gives).
  double tolerance = 0.01;
  // distress_map: the cool branch is searched on past the first failure criterion it
  // crosses only up to this factor times that load (W_d and the other criteria beyond
  // it are not searched: far past the first failure they cost minutes and lie past the
  // oil's and the model's validity). 0: none, on to load_end.
  double search_past_failure = 2.0;
  // The scene gave its speeds (study.speeds, or operating.speed where the study names
  // none) in rpm: the figures (run.json's speed_unit), the summaries and the progress
  // lines say rpm too.
  bool speeds_in_rpm = false;
  // distress_map: a search at every combination, or each followed from its neighbour's.
  MapMethod map_method = MapMethod::search;
  // transient: pseudo-time span in s; 0 marches until the state settles or runs away.
  double duration = 0.0;
  // sensitivity: the inputs differentiated against, by their scene paths (empty: every
  // input the scene file writes, Scene::inputs).
  std::vector<std::string> parameters;
  // reliability: the uncertain inputs (independent), the failure probabilities whose loads
  // are wanted (inverse FORM), and the Monte Carlo check: importance sampling round the
  // design point until the estimate's coefficient of variation is `sampling_cov` (none
  // with max_samples 0), its samples drawn from `seed`.
  std::vector<UncertainInput> uncertain_inputs;
  std::vector<double> probabilities;
  double sampling_cov = 0.1;
  int max_samples = 4000;
  long seed = 1;
  // calibration: the measurements (from the file `data`, as resolved), the inputs fitted
  // to them, and each measured quantity's standard deviation (by MeasuredQuantity; 0
  // where not given: then every residual is relative to its reading and the covariance
  // is scaled by the residuals' own variance).
  std::string data;
  std::vector<MeasuredPoint> measurements;
  std::vector<FittedInput> fitted;
  std::array<double, kMeasuredQuantities> measurement_sd{};
  int fit_iterations = 50;  // calibration: Levenberg-Marquardt iterations at most (study.max_iterations)
  // duty_cycle: the operating point in time, every field given (a field a point leaves
  // out is the point before's, the first point's the scene's operating point and gear
  // tilt); `schedule_file`: the CSV it was read from (as resolved), empty where the scene
  // lists it.
  std::vector<SchedulePoint> schedule;
  std::string schedule_file;
  // duty_cycle: the failure load at the cycle's worst moment (a failure search there).
  bool failure_load_at_worst = true;
  // duty_cycle: IDA's relative tolerance a step (study.relative_tolerance).
  double march_tolerance = 1e-6;
};

}  // namespace twb
