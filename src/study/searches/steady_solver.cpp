#include "study/searches/steady_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "solver/natural_continuation.h"
#include "solver/paper_scheme.h"
#include "solver/sparse_lu.h"
#include "study/searches/move_in_steps.h"
#include "study/study_support.h"
#include "twb/error_family.h"

namespace twb {

namespace {

NewtonSettings without_early_stop(NewtonSettings s) {
  s.watched = -1;
  s.quantities = {};
  return s;
}

}  // namespace

SteadySolver::SteadySolver(BearingModel& model, NewtonSettings settings, SparseLu::Ordering ordering)
    : model_(model), settings_(settings), newton_(model, ordering), pseudo_transient_(model, settings, newton_),
      on_the_way_(without_early_stop(settings)), ramp_transient_(model, on_the_way_, newton_) {}

SteadyReport SteadySolver::solve(std::vector<double>& u) { return settle(u, true); }

SteadyReport SteadySolver::solve_near(std::vector<double>& u) { return settle(u, true, false); }

namespace {

// A failed attempt's work, counted into the report of what came after it.
SteadyReport with_work_of(SteadyReport rep, const SteadyReport& failed) {
  rep.newton_solves += failed.newton_solves;
  rep.iterations += failed.iterations;
  rep.jacobian_evaluations += failed.jacobian_evaluations;
  rep.residual_evaluations += failed.residual_evaluations;
  rep.wall_ms += failed.wall_ms;
  rep.attempts.insert(rep.attempts.begin(), failed.attempts.begin(), failed.attempts.end());
  return rep;
}

}  // namespace

SteadyReport SteadySolver::solve_cold(std::vector<double>& u) {
  u = model_.cold_start();
  if (model_.scene().solver.method == SolverMethod::paper) return solve_by_paper(u);
  const FilmMesh& mesh = model_.films().front().mesh;
  SteadyReport spent;  // by the strategies that failed
  // A strategy that fails or throws leaves its reason; an internal error is a bug, which
  // no other strategy may hide.
  auto failed = [&](const char* strategy, const std::string& why) {
    spent.attempts.push_back(fmt::format("{}: {}", strategy, why.empty() ? "did not converge" : why));
  };
  // The coarser mesh must still be a legal one (docs/scenes.md, "Bounds"): at least
  // 5 × 24, so that it keeps interior pressure nodes and its wedge, and hold the
  // washer's grooves.
  if (mesh_sequence_ && mesh.node_count() > kSequenceAbove && (mesh.radial_nodes() + 1) / 2 >= 5 &&
      (mesh.circumferential_nodes() + 1) / 2 >= 24 &&
      model_.resolves_grooves_on((mesh.radial_nodes() + 1) / 2, (mesh.circumferential_nodes() + 1) / 2)) {
    try {
      SteadyReport rep = solve_by_mesh_sequence(u);
      if (rep.converged) return rep;
      spent = with_work_of(spent, rep);
      failed("mesh sequence", rep.message);
    } catch (const InternalError&) {
      throw;
    } catch (const std::exception& e) {
      // The cold start on the mesh itself below says what is wrong, if anything.
      failed("mesh sequence", e.what());
    }
    u = model_.cold_start();
  }
  // A washer that bends as a plate is no homotopy's: its rigid films' loads are far from
  // balanced over its faces (film 1 covers its bore, film 2 does not), and the plate's
  // answer to them, tens of micrometres, enters the gap at the homotopy's first step.
  // Coupled from the start, its cold start takes as many pseudo-time steps as the rigid
  // washer's (16 against 15 at 545 rad/s, 150 N; the homotopy took 106).
  if (model_.gap_shaped() && deformation_homotopy_ && !model_.washer_plate().elastic()) {
    try {
      SteadyReport rep = solve_by_deformation_homotopy(u);
      if (rep.converged) return with_work_of(rep, spent);
      spent = with_work_of(spent, rep);
      failed("deformation homotopy", rep.message);
    } catch (const InternalError&) {
      throw;
    } catch (const std::exception& e) {
      // As above: the deformed film's own cold start follows.
      failed("deformation homotopy", e.what());
    }
    u = model_.cold_start();
  }
  // From the paper's cold start Newton never converges: over the 36 cold starts of the
  // paper's speeds and loads (benchmarks/cold_start_survey) its 8 full steps diverged
  // and its 8 damped ones lowered the residual by a few per cent, 16 assemblies and
  // factorizations and 32 residuals wasted per state before pseudo-time, which then
  // started from the same cold state. Pseudo-time goes first: the same 36 states (to
  // 2e-16), 1468 iterations instead of 1870 (with the pseudo-time settings of then; now
  // 643, docs/model.md).
  SteadyReport rep = with_work_of(settle(u, false), spent);
  if (!rep.converged && !rep.attempts.empty()) {
    std::string before;
    for (const std::string& a : rep.attempts) before += (before.empty() ? "" : "; ") + a;
    rep.message += " (before that: " + before + ")";
  }
  return rep;
}

SteadyReport SteadySolver::solve_by_mesh_sequence(std::vector<double>& u) {
  // The mesh with every other node line, solved cold in turn (so the sequence goes down
  // to the paper's mesh or coarser), then carried here by interpolation: within
  // Newton's basin up to the coarse mesh's discretization error, where the cold start's
  // pseudo-time needs more steps on every finer mesh (benchmarks/README.md, "Growth").
  const auto t0 = std::chrono::steady_clock::now();
  const FilmMesh& mesh = model_.films().front().mesh;
  const std::unique_ptr<BearingModel> coarse =
      model_.on_mesh((mesh.radial_nodes() + 1) / 2, (mesh.circumferential_nodes() + 1) / 2);
  SteadySolver coarse_solver(*coarse, on_the_way_);
  coarse_solver.set_deformation_homotopy(deformation_homotopy_);
  std::vector<double> uc;
  SteadyReport rep = coarse_solver.solve_cold(uc);
  if (rep.converged) {
    std::vector<double> trial = model_.interpolated_from(*coarse, uc);
    rep.converged = reach(trial, rep, true);
    if (rep.converged) {
      u = std::move(trial);
      rep.message.clear();
    }
  }
  rep.strategy = "mesh sequence";
  rep.wall_ms = elapsed_ms(t0);
  return rep;
}

namespace {

// The bearing with its deformation scale as the parameter (the homotopy's continuation):
// everything else is the model's.
class DeformationScale final : public SteadySystem {
 public:
  explicit DeformationScale(BearingModel& model) : model_(model) {}
  Index size() const override { return model_.size(); }
  const SparsePattern& pattern() const override { return model_.pattern(); }
  void evaluate(std::span<const double> u, std::span<double> residual, std::span<double> jacobian) const override {
    model_.evaluate(u, residual, jacobian);
  }
  double parameter() const override { return model_.deformation_scale(); }
  void set_parameter(double value) override { model_.set_deformation_scale(value); }
  // Central differences: F is smooth in the scale, which moves only the gaps.
  void parameter_derivative(std::span<const double> u, std::span<double> derivative) const override {
    const double s = model_.deformation_scale(), h = 1e-6;
    std::vector<double> plus(derivative.size()), minus(derivative.size());
    model_.set_deformation_scale(s + h);
    model_.evaluate(u, plus, {});
    model_.set_deformation_scale(s - h);
    model_.evaluate(u, minus, {});
    model_.set_deformation_scale(s);
    for (std::size_t k = 0; k < derivative.size(); ++k) derivative[k] = (plus[k] - minus[k]) / (2.0 * h);
  }
  std::vector<double> capacities() const override { return model_.capacities(); }
  std::vector<double> step_weights() const override { return model_.step_weights(); }
  std::string block_name(Index k) const override { return model_.block_name(k); }
  std::string describe_row(Index k) const override { return model_.describe_row(k); }
  void set_newton_form(bool on) override { model_.set_newton_form(on); }
  bool newton_form() const override { return model_.newton_form(); }
  double newton_form_tolerance_ratio() const override { return model_.newton_form_tolerance_ratio(); }

 private:
  BearingModel& model_;
};

}  // namespace

SteadyReport SteadySolver::solve_by_deformation_homotopy(std::vector<double>& u) {
  // From the cold start the deformed film's pseudo-time crawls: the faces' expansion
  // follows temperatures that are themselves far from settled, and closes the film where
  // it heats (constrained faces took ~900 pseudo-time iterations at 150 N, free ones 46,
  // the rigid film 15). The rigid film's state is a few Newton steps from the deformed
  // one's at each fraction of the shapes.
  const auto t0 = std::chrono::steady_clock::now();
  // The model's own shapes (whole, unless a caller scaled them) are where the walk ends,
  // and what the model is left with however this ends, a solver's exception included.
  const double own = model_.deformation_scale();
  DeformationScale scale(model_);
  const ParameterScope own_shapes_after(scale, 0.0);
  SteadyReport rep = settle(u, false);
  if (rep.converged) {
    // Natural continuation in the scale, with its jump test: Newton from the last state
    // can land on another steady state (the deformed film has several at some loads:
    // on 5×24 at 545 rad/s, 150 N, constrained faces, a step of the scale from 0.625 to 1
    // landed on one 1 σ thinner and 3.6 K hotter than the branch's), and a corrected
    // state far from the tangent's prediction is such a jump: the step is halved.
    NaturalSettings walk;
    walk.newton = on_the_way_;
    walk.newton.max_iterations = std::min(settings_.max_iterations, 10);
    walk.initial_step = 0.25 * own;
    walk.max_step = 0.25 * own;
    walk.min_step = 0.01 * own;
    const NaturalReport r = continue_in_parameter(scale, u, 0.0, own, walk);
    ++rep.newton_solves;
    rep.iterations += r.corrector_iterations;
    rep.converged = r.reached_target;
    if (rep.converged)
      rep.message.clear();
    else
      rep.message = fmt::format("the deformation's homotopy stalled at {:.4g} of the shapes: {}", r.lambda, r.message);
  }
  rep.strategy = "deformation homotopy";
  rep.wall_ms = elapsed_ms(t0);
  return rep;
}

SteadyReport SteadySolver::solve_by_paper(std::vector<double>& u) {
  const auto t0 = std::chrono::steady_clock::now();
  PaperSchemeSettings paper;
  paper.residual_tolerance = settings_.residual_tolerance;
  paper.pressure_over_relaxation = model_.scene().solver.over_relaxation;
  paper.max_newton_iterations = settings_.max_iterations;
  const PaperSchemeReport r = solve_by_paper_scheme(model_, u, paper);
  SteadyReport rep;
  rep.strategy = "paper";
  rep.converged = r.converged;
  rep.iterations = r.newton_iterations;
  rep.jacobian_evaluations = r.evaluations;
  rep.residual_evaluations = r.evaluations;
  rep.residual_norm = r.residual_norm;
  rep.message = r.converged ? fmt::format("the paper's scheme: {} Newton-Raphson iterations, {} coupled loops, {} "
                                          "passes, {} pressure sweeps",
                                          r.newton_iterations, r.inner_solves, r.coupled_iterations,
                                          r.pressure_sweeps)
                            : "the paper's scheme: " + r.message;
  rep.wall_ms = elapsed_ms(t0);
  return rep;
}

SteadyReport SteadySolver::settle(std::vector<double>& u, bool newton_first, bool ramps) {
  const auto t0 = std::chrono::steady_clock::now();
  SteadyReport rep;
  rep.strategy = "newton";
  std::vector<double> trial = u;
  if (reach(trial, rep, newton_first)) {
    u = trial;
    rep.converged = true;
    rep.message.clear();
  } else if (ramps) {
    rep = ramp(u, rep);
  }
  rep.wall_ms = elapsed_ms(t0);
  return rep;
}

double SteadySolver::walk(const std::function<void(double)>& set, double from, double target, double step,
                          std::vector<double>& state,
                          const std::function<bool(std::vector<double>&)>& solve_step) {
  double reached = from;
  StepLength length(step, 1e-4 * target, 1.5);
  while (reached < target) {
    // A last step the target cut short is halved, where it fails, from its length before
    // the cut (unlike move_in_steps): the ramps' results depend on it.
    const double next = std::min(target, reached + length.value());
    set(next);
    std::vector<double> trial = state;
    if (solve_step(trial)) {
      state = trial;
      reached = next;
      length.lengthen();
    } else if (!length.halve()) {
      break;
    }
  }
  set(target);
  return reached;
}

bool SteadySolver::speed_ramp(std::vector<double>& u, SteadyReport& rep) {
  // The machine's own start-up: at rest the washer settles on its asperities (a small,
  // well-posed contact problem), then the speed comes up and the film builds.
  const double target = model_.speed();
  if (!(target > 0)) return false;
  model_.set_speed(0.0);
  std::vector<double> state = model_.cold_start();
  if (!ramp_transient_.reach(state, rep)) {
    model_.set_speed(target);
    return false;
  }
  NewtonSettings quick = on_the_way_;
  quick.max_iterations = 25;
  const double reached = walk([&](double w) { model_.set_speed(w); }, 0.0, target, 0.05 * target, state,
                              [&](std::vector<double>& x) { return newton(x, quick, rep); });
  if (reached < target) return false;
  u = state;
  return true;
}

SteadyReport SteadySolver::ramp(std::vector<double>& u, SteadyReport rep) {
  rep.strategy = "speed ramp";
  {
    std::vector<double> state;
    if (speed_ramp(state, rep)) {
      u = state;
      rep.converged = true;
      rep.message.clear();
      return rep;
    }
  }
  rep.strategy = "load ramp";
  const double target = model_.load();
  // Find a fraction of the load that Newton reaches from the cold start.
  std::vector<double> state;
  double start = 0.0;
  // A load the fed grooves' supply alone outweighs lifts the gear off: no start there.
  const double lift = model_.groove_supply_force();
  for (double fraction = 0.5; fraction >= 1.0 / 64.0; fraction *= 0.5) {
    if (target * fraction <= lift) break;
    model_.set_load(target * fraction);
    state = model_.cold_start();
    if (ramp_transient_.reach(state, rep)) {
      start = target * fraction;
      break;
    }
  }
  if (start == 0.0) {
    model_.set_load(target);
    rep.message = "no fraction of the load down to 1/64 converges from the cold start: " + rep.message;
    if (lift > 0.0)
      rep.message += fmt::format(
          "; the oil supply alone holds {:.4g} N on the fed grooves (lubricant.supply.pressure times their area), "
          "{} the load {:.4g} N: no steady state exists at a load the supply lifts the gear off, and the "
          "load ramp starts only above it",
          lift, lift >= target ? "more than" : "a share of", target);
    return rep;
  }
  const double reached = walk([&](double w) { model_.set_load(w); }, start, target, start, state,
                              [&](std::vector<double>& x) { return ramp_transient_.reach(x, rep); });
  if (reached < target) {
    rep.message = "load ramp stalled at " + std::to_string(reached) + " N: " + rep.message;
    return rep;
  }
  u = state;
  rep.converged = true;
  rep.message.clear();
  return rep;
}

}  // namespace twb
