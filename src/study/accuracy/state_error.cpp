#include "study/accuracy/state_error.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "study/searches/steady_solver.h"
#include "study/accuracy/mesh_convergence.h"
#include "study/accuracy/richardson.h"
#include "study/study_support.h"
#include "twb/results/run_axes.h"

namespace twb {

namespace {

// How closely the refined state's quantities are solved: a part of their distance from
// the coarse ones (refine_state).
constexpr double kRefinedSettling = 1e-3;

// Where quantity k is counted from when its error is taken relative: temperatures (degC)
// from the ambient, so that their error is relative to the rise; the rest from zero.
double zero_of(const Scene& scene, std::size_t k) {
  return k < kMeshErrorTemperatures ? scene.operating.ambient - 273.15 : 0.0;
}

// How far a state's quantity k is from its extrapolation, relative (zero_of).
double relative_offset(const Scene& scene, std::size_t k, double coarse, double extrapolated) {
  return std::abs(coarse - extrapolated) / std::max(std::abs(extrapolated - zero_of(scene, k)), 1e-300);
}

}  // namespace

std::unique_ptr<BearingModel> refined_model(const BearingModel& model, std::string& why) {
  const Scene refined = refined_mesh(model.scene());
  if (refined.mesh.radial_nodes > 65 || refined.mesh.circumferential_nodes > 528) {
    why = fmt::format("the refined {} mesh is beyond the 65 x 528 twb refines a state on (study.error_estimate: "
                      "none leaves it out)",
                      mesh_name(refined));
    return nullptr;
  }
  return model.on_mesh(refined.mesh.radial_nodes, refined.mesh.circumferential_nodes);
}

namespace {

// Why a state gets no error bar before any refined solve: past the contact model's
// validity, where a finer mesh would resolve a state with no meaning, at a cost far above
// its own.
bool past_contact_model(const SolvedState& state, std::string& why) {
  for (const LimitExcess& e : state.state.limits)
    if (e.kind == LimitKind::contact_pressure) {
      why = fmt::format("the state is past the contact model's validity ({})", describe_limit(e));
      return true;
    }
  return false;
}

// The state solved at `u` on `coarse` (its quantities `coarse_values`) again on `fine`
// at the same load, from its interpolation: the refined unknowns in v and quantities in
// values, or false with the reason in `why`.
bool solve_refined(const BearingModel& coarse, BearingModel& fine, std::span<const double> u,
                   const std::vector<double>& coarse_values, SparseLu::Ordering ordering, std::vector<double>& v,
                   std::vector<double>& values, std::string& why, long* newton_iterations, long* jacobians) {
  fine.set_load(coarse.load());
  v = fine.interpolated_from(coarse, u);
  // The bars need the refined quantities to a small part of their distance from the
  // coarse ones only: Newton stops at the first point whose quantities are within 1e-3
  // of that distance of the root's (settled_by_contraction), or at the tolerance,
  // whichever comes first. The point is then accepted with its quantities read (a
  // residual pass) but without the Jacobian, factorization and step past it that a test
  // on that step would need. Read on Newton's undamped steps only (their points are
  // consecutive iterates); a solve that needs the line search or the fallbacks
  // converges to the tolerance.
  // The bar differs from the fully converged one's by at most about 1e-3 of itself.
  NewtonSettings newton = newton_settings(coarse.scene());
  std::vector<double> described_at, described;  // the last point the quantities were read at
  newton.quantities.at = [&](std::span<const double> w) {
    described_at.assign(w.begin(), w.end());
    described = mesh_error_quantities(fine.describe(w));
    return described;
  };
  newton.quantities.settled = [&](const NewtonSettings::QuantityReads& reads) {
    return settled_by_contraction(
        reads, [&](std::size_t k, double value) { return kRefinedSettling * std::abs(value - coarse_values[k]); });
  };
  // From the interpolated state alone (Newton, then pseudo-time from it): the ramps from
  // the cold start would cost many times the point and reach a state that owes nothing
  // to the coarse one.
  SteadySolver solver(fine, newton, ordering);
  const SteadyReport rep = solver.solve_near(v);
  if (newton_iterations) *newton_iterations += rep.iterations;
  if (jacobians) *jacobians += rep.jacobian_evaluations;
  if (!rep.converged) {
    why = fmt::format("no steady state on the refined {} mesh at {:.6g} N: {}", mesh_name(fine.scene()),
                      coarse.load(), rep.message);
    return false;
  }
  values = v == described_at ? described : mesh_error_quantities(fine.describe(v));
  return true;
}

}  // namespace

bool refine_state(const BearingModel& model, BearingModel& fine, std::span<const double> u, SolvedState& state,
                  std::string& why, SparseLu::Ordering ordering, long* newton_iterations, long* jacobians) {
  if (past_contact_model(state, why)) return false;
  const std::vector<double> coarse = mesh_error_quantities(state.state);
  std::vector<double> v, fine_values;
  if (!solve_refined(model, fine, u, coarse, ordering, v, fine_values, why, newton_iterations, jacobians))
    return false;
  state.mesh_errors.clear();
  for (std::size_t k = 0; k < coarse.size(); ++k) {
    const MeshErrorEstimate e = richardson_extrapolation(coarse[k], fine_values[k], kTwoGridSafety);
    state.mesh_errors.push_back(e.extrapolated);
    state.mesh_errors.push_back(e.error);
  }
  return true;
}

bool refine_state_to_tolerance(const BearingModel& model, std::span<const double> u, SolvedState& state,
                               double tolerance, std::vector<std::string>& lines, std::string& why,
                               long* newton_iterations, long* jacobians) {
  if (past_contact_model(state, why)) return false;
  const Scene& scene = model.scene();
  constexpr std::size_t quantities = std::size(kMeshErrorQuantities);
  // Each quantity on each mesh solved, the scene's first.
  std::vector<std::vector<double>> on_mesh{mesh_error_quantities(state.state)};
  std::string meshes = mesh_name(scene), stopped;
  std::vector<std::unique_ptr<BearingModel>> solved;
  const BearingModel* from = &model;
  std::vector<double> at(u.begin(), u.end());
  std::vector<MeshConvergence> estimate(quantities);
  // The hottest node is a node's value, with no order in the mesh (physics §8, "The oil's
  // peak temperature"): it has its bar, but the tolerance holds its located counterpart,
  // T_oil_peak_C, not it.
  auto held = [](std::size_t k) { return std::string_view(kMeshErrorQuantities[k]) != "T_max_C"; };
  auto estimate_all = [&] {
    bool met = true;
    for (std::size_t k = 0; k < quantities; ++k) {
      std::vector<double> values;
      for (const std::vector<double>& q : on_mesh) values.push_back(q[k] - zero_of(scene, k));
      estimate[k] = mesh_converged(values);
      met = met && (!held(k) || within_tolerance(estimate[k], tolerance));
    }
    return met;
  };
  bool met = false;
  for (const Scene& refined : refined_meshes(scene)) {
    if (refined.mesh.radial_nodes > 65 || refined.mesh.circumferential_nodes > 528) {
      stopped = fmt::format("the {} mesh is beyond the 65 x 528 twb refines a state on", mesh_name(refined));
      break;
    }
    std::unique_ptr<BearingModel> fine = model.on_mesh(refined.mesh.radial_nodes, refined.mesh.circumferential_nodes);
    std::vector<double> v, values;
    if (!solve_refined(*from, *fine, at, on_mesh.back(), SparseLu::Ordering::minimum_degree, v, values, stopped,
                       newton_iterations, jacobians))
      break;
    on_mesh.push_back(std::move(values));
    meshes += fmt::format(", {}", mesh_name(refined));
    solved.push_back(std::move(fine));
    from = solved.back().get();
    at = std::move(v);
    if ((met = estimate_all())) break;
  }
  if (on_mesh.size() < 2) {
    why = stopped;
    return false;
  }
  state.mesh_errors.clear();
  std::string unmet;
  for (std::size_t k = 0; k < quantities; ++k) {
    const double zero = zero_of(scene, k);
    state.mesh_errors.push_back(estimate[k].value + zero);
    state.mesh_errors.push_back(estimate[k].error);
    if (held(k) && !within_tolerance(estimate[k], tolerance))
      unmet += fmt::format("{}{} {:.4g} ± {:.2g} ({:.1f} %{})", unmet.empty() ? "" : ", ", kMeshErrorQuantities[k],
                           estimate[k].value + zero, estimate[k].error,
                           100.0 * estimate[k].error / std::max(std::abs(estimate[k].value), 1e-300),
                           k < kMeshErrorTemperatures ? " of its rise" : "");
  }
  lines.push_back(fmt::format("error bars to {:g} % from {}: states.csv's *_extrapolated and *_error columns "
                              "(T_max_C, the hottest node, has no order and is not held to it: T_oil_peak_C is "
                              "the located peak)",
                              100.0 * tolerance, meshes));
  if (!met)
    lines.push_back(fmt::format("warning: not every quantity within {:g} %: {}{}", 100.0 * tolerance, unmet,
                                stopped.empty() ? fmt::format(" after mesh.max_refinements: {}", scene.mesh.max_refinements)
                                                : " (" + stopped + ")"));
  return true;
}

std::vector<std::string> state_error_lines(const Scene& scene, const std::vector<SolvedState>& states) {
  std::vector<const SolvedState*> with;
  for (const SolvedState& s : states)
    if (!s.mesh_errors.empty()) with.push_back(&s);
  if (with.empty()) return {};
  const Scene refined = refined_mesh(scene);
  const std::string fine = mesh_name(refined);
  std::vector<std::string> lines;
  lines.push_back(
      with.size() == 1 && states.size() == 1
          ? fmt::format("error bars from the {} mesh: states.csv's *_extrapolated and *_error columns", fine)
          : fmt::format("error bars from the {} mesh at {} of {} states: states.csv's *_extrapolated and *_error "
                        "columns",
                        fine, with.size(), states.size()));
  // The worst offset of each quantity over the states, and where.
  constexpr std::size_t quantities = std::size(kMeshErrorQuantities);
  std::vector<double> worst(quantities, 0.0);
  std::vector<const SolvedState*> where(quantities, nullptr);
  std::size_t states_beyond = 0;
  for (const SolvedState* s : with) {
    const std::vector<double> coarse = mesh_error_quantities(s->state);
    bool beyond = false;
    for (std::size_t k = 0; k < quantities; ++k) {
      const double off = relative_offset(scene, k, coarse[k], s->mesh_errors[2 * k]);
      if (off > 0.05) beyond = true;
      if (off > worst[k]) {
        worst[k] = off;
        where[k] = s;
      }
    }
    if (beyond) ++states_beyond;
  }
  std::string listed;
  double largest = 0.0;
  for (std::size_t k = 0; k < quantities; ++k) {
    if (!(worst[k] > 0.05)) continue;
    largest = std::max(largest, worst[k]);
    const SolvedState& s = *where[k];
    const double value = mesh_error_quantities(s.state)[k];
    listed += fmt::format("{}{} {:.4g} ({:.1f} % from its mesh-converged {:.4g} ± {:.2g}{})", listed.empty() ? "" : ", ",
                          kMeshErrorQuantities[k], value, 100.0 * worst[k], s.mesh_errors[2 * k],
                          s.mesh_errors[2 * k + 1],
                          with.size() == 1 ? std::string()
                                           : fmt::format(" at {:.6g} N, {}", s.state.load,
                                                         speed_text(s.state.speed, scene.study.speeds_in_rpm)));
  }
  if (listed.empty()) return lines;
  // The error falls as h^2: refining by r divides it by r^2.
  const double r = std::ceil(std::sqrt(largest / 0.05));
  const MeshSettings& m = scene.mesh;
  lines.push_back(fmt::format("warning: the scene's {} x {} mesh is more than 5 % off{}: {}; a mesh of about {} x {} "
                              "would meet 5 %",
                              m.radial_nodes, m.circumferential_nodes,
                              with.size() == 1 ? std::string()
                                               : fmt::format(" at {} of {} states (the worst of each quantity)",
                                                             states_beyond, with.size()),
                              listed, int(r) * (m.radial_nodes - 1) + 1, int(r) * m.circumferential_nodes));
  return lines;
}

}  // namespace twb
