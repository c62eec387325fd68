#include "study/uncertainty/crossing_response.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "model/limit_thresholds.h"
#include "study/searches/failure_load.h"
#include "study/searches/steady_solver.h"
#include "study/study_support.h"

namespace twb {

namespace {

// The criterion's margin of state u of model m, against m's own scene's limits (a limit
// can be the input itself).
double margin_of(const BearingModel& m, LimitKind kind, std::span<const double> u) {
  const std::optional<double> margin = state_margin(m, u, kind, OperatingLimits::of(m.scene()));
  // A criterion the base applies that a neighbour does not (an input that switches it off).
  if (!margin) throw std::invalid_argument(fmt::format("the criterion {} does not apply", limit_name(kind)));
  return *margin;
}

}  // namespace

std::optional<SettledCrossing> settle_crossing(BearingModel& model, LimitKind kind, double load,
                                               std::vector<double> u, std::string& why) {
  const ParameterScope keep(model);
  SettledCrossing c;
  c.kind = kind;
  c.lu = std::make_unique<SparseLu>(model.pattern(), SparseLu::Ordering::minimum_degree);
  SteadySolver solver(model, newton_settings(model.scene()));
  const auto n = std::size_t(model.size());
  std::vector<double> f(n), jac(std::size_t(model.pattern().nnz())), u_load(n);
  // The margin's root to a billionth of the load: far below the state's own accuracy's
  // effect on it. Newton converges quadratically from the search's bracket width.
  for (int step = 0; step < 8; ++step) {
    // (Solved at the first step too: u may be another model's state, or one to the
    // search's tolerance only.)
    model.set_load(load);
    const SteadyReport rep = solver.solve(u);
    if (!rep.converged) {
      why = fmt::format("the branch was lost at {:.6g} N settling the crossing: {}", load, rep.message);
      return std::nullopt;
    }
    model.evaluate(u, f, jac);
    if (!c.lu->factor(jac)) {
      why = fmt::format("the Jacobian is singular at the crossing, {:.6g} N", load);
      return std::nullopt;
    }
    model.parameter_derivative(u, u_load);
    c.lu->solve(u_load);  // J⁻¹F_W: the state moves by −u_load per newton
    const double dw = kInputStep * load;
    c.margin_slope = stencil_derivative(kCentred, dw, [&](std::size_t k) {
      const double s = kCentred.offsets[k] * dw;
      model.set_load(load + s);
      return std::vector<double>{margin_of(model, kind, moved_state(u, u_load, s))};
    })[0];
    model.set_load(load);
    const double margin = margin_of(model, kind, u);
    if (!(std::abs(c.margin_slope) > 0.0)) {
      why = fmt::format("the margin does not change with load at the crossing, {:.6g} N", load);
      return std::nullopt;
    }
    double move = -margin / c.margin_slope;
    if (std::abs(move) <= 1e-9 * load) {
      c.load = load;
      c.u = std::move(u);
      return c;
    }
    // Where the margin is nearly flat in load, Newton's step may reach a load the bearing
    // cannot take: it goes at most half the way to zero, and the root not settled in the
    // steps allowed is reported as such.
    if (!(load + move > 0.0)) move = -0.5 * load;
    load += move;
  }
  why = fmt::format("the margin's root was not settled near {:.6g} N", load);
  return std::nullopt;
}

double crossing_load_derivative(InputNeighbours& n, const SettledCrossing& crossing, std::mutex& solve_lock) {
  std::vector<double> u_p = residual_derivative(n, crossing.u, crossing.load);
  {
    const std::lock_guard<std::mutex> hold(solve_lock);
    crossing.lu->solve(u_p);
  }
  const double margin_input = n.derivative([&](std::size_t k) {
    n.at[k]->set_load(n.load_at(k, crossing.load));
    return std::vector<double>{margin_of(*n.at[k], crossing.kind, moved_state(crossing.u, u_p, n.stencil.offsets[k] * n.step))};
  })[0];
  return -margin_input / crossing.margin_slope;
}

}  // namespace twb
