#include "study/measured_response.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>

#include <fmt/format.h>

#include "model/bearing_model.h"
#include "solver/sparse_lu.h"
#include "study/input_neighbours.h"
#include "study/operating_point.h"
#include "study/parallel.h"
#include "study/sensitivity.h"
#include "study/steady_solver.h"
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
    auto same = std::find_if(speeds_.begin(), speeds_.end(),
                             [&](const std::vector<std::size_t>& g) { return points_[g.front()].speed == points_[i].speed; });
    if (same == speeds_.end()) speeds_.emplace_back(1, i);
    else same->push_back(i);
  }
  for (std::vector<std::size_t>& g : speeds_)
    std::stable_sort(g.begin(), g.end(), [&](std::size_t a, std::size_t b) { return points_[a].load < points_[b].load; });
  lightest_.resize(speeds_.size());
}

bool MeasuredResponse::predict(std::span<const double> p, bool with_derivatives, std::vector<PointPrediction>& out,
                               std::string& why) {
  std::vector<std::pair<std::string, double>> set;
  for (std::size_t j = 0; j < fitted_.size(); ++j) set.emplace_back(fitted_[j].path, p[j]);
  const Scene at = with_inputs(scene_, set);
  out.assign(points_.size(), PointPrediction{});
  std::vector<std::string> failed(points_.size());
  std::vector<long> solves(points_.size(), 0);
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
      std::vector<double> u = lightest_[g];
      for (std::size_t i : speeds_[g]) {
        const MeasuredPoint& m = points_[i];
        model.set_speed(m.speed);
        model.set_load(m.load);
        SteadySolver solver(model, newton_settings(at), SparseLu::Ordering::minimum_degree);
        const SteadyReport rep = u.empty() ? solver.solve_cold(u) : solver.solve(u);
        ++solves[i];
        if (!rep.converged) {
          failed[i] = fmt::format("no steady state at the measured point of line {} ({:.6g} N, {:.6g} rad/s): {}",
                                  m.line, m.load, m.speed, rep.message);
          break;  // the heavier points of this speed have no state to start from
        }
        if (i == speeds_[g].front()) lightest_[g] = u;
        PointPrediction& pred = out[i];
        pred.state = recorded_state(model, u, rep);
        const std::vector<StateQuantity> q = state_quantities(pred.state.state);
        for (std::size_t k = 0; k < kMeasuredQuantities; ++k) pred.values[k] = q[k].value;
        if (!with_derivatives) continue;
        std::vector<double> f(u.size()), jac(std::size_t(model.pattern().nnz()));
        model.evaluate(u, f, jac);
        SparseLu lu(model.pattern(), SparseLu::Ordering::minimum_degree);
        if (!lu.factor(jac)) {
          failed[i] = fmt::format("the state at the measured point of line {} has a singular Jacobian (a fold): it "
                                  "does not move smoothly with the inputs",
                                  m.line);
          break;
        }
        for (std::size_t k = 0; k < kMeasuredQuantities; ++k) pred.derivatives[k].assign(fitted_.size(), 0.0);
        for (std::size_t j = 0; j < fitted_.size(); ++j) {
          for (auto& neighbour : neighbours[j].at) neighbour->set_speed(m.speed);
          const std::vector<double> d = state_derivatives(neighbours[j], u, m.load, lu, solve_lock);
          for (std::size_t k = 0; k < kMeasuredQuantities; ++k) pred.derivatives[k][j] = d[k];
        }
      }
    }
  });
  for (long s : solves) solves_ += s;
  for (const std::string& f : failed)
    if (!f.empty()) {
      why = f;
      return false;
    }
  return true;
}

}  // namespace twb
