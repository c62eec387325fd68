#include "study/uncertainty/measured_response.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>

#include <fmt/format.h>

#include "model/bearing_model.h"
#include "solver/natural_continuation.h"
#include "solver/sparse_lu.h"
#include "study/uncertainty/input_neighbours.h"
#include "study/searches/operating_point.h"
#include "study/parallel/parallel.h"
#include "study/uncertainty/sensitivity.h"
#include "study/searches/steady_solver.h"
#include "study/study_support.h"
#include "twb/error_family.h"
#include "twb/scene/scene_inputs.h"

namespace twb {

MeasuredResponse::MeasuredResponse(Scene scene, std::vector<FittedInput> fitted, std::vector<MeasuredPoint> points,
                                   int threads)
    : scene_(std::move(scene)),
      fitted_(std::move(fitted)),
      points_(std::move(points)),
      threads_(std::max(threads, 1)) {
  for (std::size_t i = 0; i < points_.size(); ++i) {
    // (a rig runs up the load at one speed and one oil temperature at a time)
    auto same = std::find_if(speeds_.begin(), speeds_.end(), [&](const std::vector<std::size_t>& g) {
      return points_[g.front()].speed == points_[i].speed && points_[g.front()].ambient == points_[i].ambient;
    });
    if (same == speeds_.end()) speeds_.emplace_back(1, i);
    else same->push_back(i);
  }
  for (std::vector<std::size_t>& g : speeds_)
    std::stable_sort(g.begin(), g.end(), [&](std::size_t a, std::size_t b) { return points_[a].load < points_[b].load; });
  lightest_.resize(speeds_.size());
  own_ambient_ = std::any_of(points_.begin(), points_.end(), [](const MeasuredPoint& m) { return m.ambient > 0.0; });
}

bool MeasuredResponse::predict(std::span<const double> p, bool with_derivatives, std::vector<PointPrediction>& out,
                               std::string& why) {
  const bool again = !last_p_.empty() && std::equal(p.begin(), p.end(), last_p_.begin(), last_p_.end());
  if (again && !with_derivatives) {
    out = last_;
    return true;
  }
  std::vector<std::pair<std::string, double>> set;
  for (std::size_t j = 0; j < fitted_.size(); ++j) set.emplace_back(fitted_[j].path, p[j]);
  const Scene at = with_inputs(scene_, set);
  out.assign(points_.size(), PointPrediction{});
  std::vector<std::vector<double>> states = again ? states_ : std::vector<std::vector<double>>(points_.size());
  std::vector<std::string> failed(points_.size());
  std::vector<long> solves(points_.size(), 0);
  NaturalSettings natural;
  natural.newton = newton_settings(at);
  natural.newton.max_iterations = 12;
  // The speeds in as many consecutive runs as threads, each on a bearing (and, for the
  // derivatives, the inputs' neighbours) of its own.
  const std::size_t runs = std::min<std::size_t>(std::size_t(threads_), speeds_.size());
  run_in_parallel(runs, int(runs), [&](std::size_t r) {
    BearingModel model(at);
    std::vector<InputNeighbours> neighbours;
    if (with_derivatives)
      for (const FittedInput& f : fitted_) neighbours.push_back(input_neighbours(model, scene_input(at, f.path), 2));
    std::mutex solve_lock;  // this run's own: its factors are its own
    for (std::size_t g = r * speeds_.size() / runs; g < (r + 1) * speeds_.size() / runs; ++g) {
      for (std::size_t k = 0; k < speeds_[g].size(); ++k) {
        const std::size_t i = speeds_[g][k];
        const MeasuredPoint& m = points_[i];
        std::vector<double>& u = states[i];
        model.set_speed(m.speed);
        // The point's own oil temperature where the data give one, else the scene's (on the
        // neighbours too, in differentiate: they stand at the scene's, which the fit does
        // not move then: read_calibration refuses fitting operating.ambient).
        const double ambient = m.ambient > 0.0 ? m.ambient : at.operating.ambient;
        if (own_ambient_) model.set_curve_parameter(CurveParameter::ambient_temperature, ambient);
        if (again) {
          model.set_load(m.load);
          out[i] = last_[i];
        } else {
          const std::span<const double> before = k > 0 ? std::span<const double>(states[speeds_[g][k - 1]])
                                                       : std::span<const double>();
          if (!solve_point(model, g, k, before, u, natural, out[i], failed[i], solves[i])) break;
        }
        if (!with_derivatives) continue;
        if (!differentiate(model, neighbours, solve_lock, m, ambient, u, out[i], failed[i])) break;
      }
    }
  });
  for (long s : solves) solves_ += s;
  for (const std::string& f : failed)
    if (!f.empty()) {
      why = f;
      return false;
    }
  last_p_.assign(p.begin(), p.end());
  states_ = std::move(states);
  last_ = out;
  for (PointPrediction& pred : last_)
    for (std::vector<double>& d : pred.derivatives) d.clear();
  return true;
}

bool MeasuredResponse::solve_point(BearingModel& model, std::size_t g, std::size_t k,
                                   std::span<const double> state_before, std::vector<double>& u,
                                   const NaturalSettings& settings, PointPrediction& pred, std::string& failed,
                                   long& solves) {
  const MeasuredPoint& m = points_[speeds_[g][k]];
  SteadyReport rep;
  if (k == 0) {
    // The lightest point from a fixed state: what it converges to depends on the inputs only.
    u = lightest_[g];
    model.set_load(m.load);
    SteadySolver solver(model, newton_settings(model.scene()), SparseLu::Ordering::minimum_degree);
    rep = u.empty() ? solver.solve_cold(u) : solver.solve(u);
    ++solves;
    if (!rep.converged) {
      failed = fmt::format("no steady state at the measured point of line {} ({:.6g} N, {:.6g} rad/s): {}", m.line,
                           m.load, m.speed, rep.message);
      return false;
    }
    if (lightest_[g].empty()) lightest_[g] = u;
  } else {
    // On from the point before, along the branch: a step that jumps to another is
    // shortened, and past the branch's fold no step reaches the load.
    const double before = points_[speeds_[g][k - 1]].load;
    u.assign(state_before.begin(), state_before.end());
    NaturalSettings natural = settings;
    const double step = m.load - before;
    if (step > 0.0) {
      natural.initial_step = natural.max_step = step;
      natural.min_step = 1e-3 * step;
      model.set_load(before);
      const NaturalReport nr = continue_in_parameter(model, u, before, m.load, natural);
      ++solves;
      if (!nr.reached_target) {
        failed = fmt::format("the measured point of line {} ({:.6g} N, {:.6g} rad/s) lies past the fold of the branch "
                             "continued from the light load (continuation stopped at {:.6g} N: {})",
                             m.line, m.load, m.speed, nr.lambda, nr.message);
        return false;
      }
      rep.iterations = nr.corrector_iterations;
    }
    model.set_load(m.load);
    rep.converged = true;
    rep.strategy = "continuation";
  }
  pred.state = recorded_state(model, u, rep);
  const std::vector<StateQuantity> q = state_quantities(pred.state.state);
  for (std::size_t j = 0; j < kMeasuredQuantities; ++j) pred.values[j] = q[j].value;
  return true;
}

bool MeasuredResponse::differentiate(BearingModel& model, std::vector<InputNeighbours>& neighbours,
                                     std::mutex& solve_lock, const MeasuredPoint& m, double ambient,
                                     std::span<const double> u, PointPrediction& pred, std::string& failed) const {
  const std::unique_ptr<SparseLu> factors = jacobian_factors(model, u);
  if (!factors) {
    failed = fmt::format("the state at the measured point of line {} has a singular Jacobian (a fold): it does not "
                         "move smoothly with the inputs",
                         m.line);
    return false;
  }
  for (std::size_t k = 0; k < kMeasuredQuantities; ++k) pred.derivatives[k].assign(fitted_.size(), 0.0);
  for (std::size_t j = 0; j < fitted_.size(); ++j) {
    for (auto& neighbour : neighbours[j].at) {
      neighbour->set_speed(m.speed);
      if (own_ambient_) neighbour->set_curve_parameter(CurveParameter::ambient_temperature, ambient);
    }
    const std::vector<double> d = state_derivatives(neighbours[j], u, m.load, *factors, solve_lock);
    for (std::size_t k = 0; k < kMeasuredQuantities; ++k) pred.derivatives[k][j] = d[k];
  }
  return true;
}

}  // namespace twb
