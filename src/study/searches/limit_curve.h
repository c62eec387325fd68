// A failure criterion's crossing continued in a second parameter (study type
// distress_curve, docs/physics.md section 8): beside the fold curve, the load where the
// cool branch crosses the oil's, the flash or a material's temperature limit, or the least
// film ratio, as the curve parameter goes across its range. From the crossing at one end,
// each step sets the parameter a step further, predicts the crossing's load and state
// through the last three crossings (a parabola in the parameter), corrects the state by
// Newton at the predicted load (the last crossing's where Newton cannot start from the
// prediction; the step is halved where neither converges), then moves the load to the
// crossing by secant steps on the margin to the search's width (failure_load.h:
// crossing_near); one Newton solver serves the whole curve. The curve ends at the range's
// end, where the crossing passes load_end, or where the branch folds before reaching it
// (there the fold curve is the boundary).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/bearing_model.h"
#include "twb/model/bearing_state.h"

namespace twb {

struct LimitCurveSettings {
  int steps = 24;               // equal steps across the range, each halved up to 6 times where needed
  double bracket_width = 0.002;  // relative: how closely each crossing is located
  double load_end = 0.0;        // N: above it a crossing is not followed
  // W_d at a parameter value where the cool branch folds, none where it does not (past a
  // cusp): a crossing at or above it would lie on the hot branch, and the curve ends
  // there (the fold comes first).
  std::function<std::optional<double>(double)> fold_load;
  // Each point's crossing again on the mesh refined by two (study.error_estimate), and
  // with a tolerance (relative, study.tolerance; 0: none) on finer meshes until its bar
  // meets it (richardson.h: crossing_sequence).
  bool error_bars = false;
  double tolerance = 0.0;
  // A parameter value as the curve's end says it ("4125 rpm"); none: the number alone.
  std::function<std::string(double)> shown;
};

struct LimitCurvePoint {
  double p = 0.0;  // the curve parameter (SI)
  BearingState state;  // at the crossing; state.load is the crossing's load
  std::vector<double> u;  // the state there (the start of its error bar's refined crossings)
};

struct LimitCurve {
  LimitKind kind = LimitKind::oil_temperature;
  std::vector<LimitCurvePoint> points;  // from the start, the first point the start's crossing
  std::string ended;                    // why it ended before the range's end, if it did
  long solves = 0;                      // steady solves (Newton corrections, continuations)
};

// From `crossing` (load, state) at parameter `from` to `to`. The model comes back at the
// load it was given (a ParameterScope); its curve parameter is left at the last point's
// (a curve is traced on a model of its own: restoring a roughness would replace the
// scene's surfaces by uniform ones).
LimitCurve trace_limit_curve(BearingModel& model, CurveParameter which, LimitKind kind, double from, double to,
                             std::pair<double, std::vector<double>> crossing, const LimitCurveSettings& settings);

}  // namespace twb
