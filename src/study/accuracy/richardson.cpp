#include "study/accuracy/richardson.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "study/uncertainty/input_neighbours.h"
#include "study/study_support.h"
#include "study/searches/failure_load.h"
#include "model/face_relief.h"
#include "model/limit_thresholds.h"
#include "solver/kinsol_newton.h"
#include "twb/error_family.h"

namespace twb {

namespace {

constexpr double formal_order = 2.0;

}  // namespace

MeshErrorEstimate richardson_extrapolation(double coarse, double fine, double safety) {
  MeshErrorEstimate e;
  e.fine_fold = fine;
  const double change = (fine - coarse) / (std::pow(2.0, formal_order) - 1.0);
  e.extrapolated = fine + change;
  e.error = safety * std::abs(change);
  return e;
}

MeshErrorEstimate sequence_estimate(const MeshSequence& sequence, double tolerance, const std::string& finest) {
  const std::vector<double>& loads = sequence.loads();
  MeshErrorEstimate e;
  if (tolerance <= 0.0) {
    e = richardson_extrapolation(loads[0], loads[1]);
  } else {
    const MeshConvergence c = sequence.estimate();
    e.fine_fold = loads.back();
    e.extrapolated = c.value;
    e.error = c.error;
    e.convergence.order = c.order;
    e.convergence.tolerance_met = within_tolerance(c, tolerance);
    if (!*e.convergence.tolerance_met) e.convergence.why_unmet = sequence.why_unmet(tolerance);
  }
  e.fine_mesh = finest;
  e.convergence.meshes = sequence.solved_meshes();
  return e;
}

std::string mesh_name(const Scene& scene) {
  return fmt::format("{} x {}", scene.mesh.radial_nodes, scene.mesh.circumferential_nodes);
}

Scene refined_mesh(const Scene& scene) {
  Scene fine = scene;
  fine.mesh.radial_nodes = 2 * (scene.mesh.radial_nodes - 1) + 1;
  fine.mesh.circumferential_nodes = 2 * scene.mesh.circumferential_nodes;
  // The grooves keep their angles and their dam its radius: twice the cells, twice the
  // dam's line (physics section 14), which every grid refined by two can hold.
  if (scene.washer.grooves) {
    fine.washer.grooves =
        grooves_on_grid(*scene.washer.grooves, {scene.mesh.radial_nodes, scene.mesh.circumferential_nodes},
                        {fine.mesh.radial_nodes, fine.mesh.circumferential_nodes});
    if (!fine.washer.grooves) throw InternalError("refined_mesh: the grooves do not lie on the grid refined by two");
  }
  return fine;
}

namespace {

MeshErrorEstimate extrapolated(double coarse, double fine, const std::string& mesh) {
  MeshErrorEstimate e = richardson_extrapolation(coarse, fine);
  e.fine_mesh = mesh;
  return e;
}


// A difference of two states carried onto the refined mesh (the interpolation is affine
// in the state: the edge values and the ambient shift cancel).
std::vector<double> moved_difference(const BearingModel& fine, const BearingModel& coarse, std::span<const double> a,
                                     std::span<const double> b) {
  std::vector<double> d = fine.interpolated_from(coarse, a);
  const std::vector<double> base = fine.interpolated_from(coarse, b);
  for (std::size_t k = 0; k < d.size(); ++k) d[k] -= base[k];
  return d;
}

// A direction v at the coarse state u (a null vector) carried onto the refined mesh.
std::vector<double> moved_direction(const BearingModel& fine, const BearingModel& coarse, std::span<const double> u,
                                    std::span<const double> v) {
  std::vector<double> shifted(u.begin(), u.end());
  for (std::size_t k = 0; k < shifted.size(); ++k) shifted[k] += v[k];
  return moved_difference(fine, coarse, shifted, u);
}

// The fold found from a guess, checked: converged, of the coarse fold's kind (the sign
// of its curvature), and within 30 % of the coarse load (the coarsest legal meshes put
// W_d about 20 % low: benchmarks/README.md, "What accuracy costs: W_d"). Newton gets 20
// iterations: from the coarse fold it takes 8 on the paper's bearing, 4 to 6 along a
// curve, and each iteration costs three Jacobians and a bordered factorization on the
// refined mesh, so a guess outside its reach is given up early.
// load_accuracy (N, 0: the residual tolerance alone): how closely the fold's load is
// needed (locate_fold_near).
std::optional<FoldPoint> checked_fold(BearingModel& fine, std::span<const double> u, double load,
                                      std::span<const double> null_guess, double coarse_load, int kind,
                                      std::string& why, double load_accuracy = 0.0) {
  NewtonSettings newton = newton_settings(fine.scene());
  newton.max_iterations = std::min(newton.max_iterations, 20);
  FoldPoint fold = locate_fold_near(fine, u, load, null_guess, newton, load_accuracy);
  if (fold.u.empty()) {
    why = fold.message;
    return std::nullopt;
  }
  if (!(fold.curvature * kind > 0.0)) {
    why = fmt::format("the fold found at {:.6g} N is not a {} load (curvature {:.3g})", fold.lambda,
                      kind > 0 ? "largest" : "smallest", fold.curvature);
    return std::nullopt;
  }
  if (!(std::abs(fold.lambda - coarse_load) <= 0.3 * coarse_load)) {
    why = fmt::format("the fold found at {:.6g} N is too far from the coarse fold at {:.6g} N", fold.lambda,
                      coarse_load);
    return std::nullopt;
  }
  return fold;
}

}  // namespace


std::optional<FoldPoint> fold_on_finer_mesh(const BearingModel& coarse, const FoldPoint& at, BearingModel& fine,
                                            double load_accuracy, std::string& why) {
  return checked_fold(fine, fine.interpolated_from(coarse, at.u), at.lambda,
                      moved_direction(fine, coarse, at.u, at.null_vector), at.lambda, +1, why, load_accuracy);
}

std::optional<RefinedFold> refined_fold(const Scene& scene, double speed, const CoarseFold& coarse,
                                        DistressSearchSettings settings, std::string& why,
                                        const SearchProgress& progress) {
  const Scene fine_scene = refined_mesh(scene);
  RefinedFold refined;
  // From the coarse model where there is one: it carries what its scene does not (a curve's
  // viscosity scale).
  refined.model = coarse.model ? coarse.model->on_mesh(fine_scene.mesh.radial_nodes, fine_scene.mesh.circumferential_nodes)
                               : std::make_unique<BearingModel>(fine_scene);
  BearingModel& fine = *refined.model;
  fine.set_speed(speed);
  const std::string mesh = mesh_name(fine_scene);
  const auto say = [&](const std::string& s) {
    if (progress) progress("  [" + mesh + "]" + s);
  };
  if (coarse.model && coarse.point) {
    std::string direct_why;
    FoldPoint from = *coarse.point;
    from.lambda = coarse.load;
    refined.point = fold_on_finer_mesh(*coarse.model, from, fine, 0.0, direct_why);
    if (refined.point) {
      refined.load = refined.point->lambda;
      say(fmt::format("  the fold from the coarse mesh's: {:.2f} N", refined.load));
      return refined;
    }
    say("  the fold from the coarse mesh's failed (" + direct_why + "); continuing the branch instead");
  }
  settings.fold_only = true;
  settings.grid.clear();
  settings.continue_past_distress = false;
  DistressSearch found = search_distress(fine, settings, progress ? SearchProgress(say) : SearchProgress{});
  if (!found.row.fold_load) {
    why = fmt::format("no fold on the refined mesh ({}): {}", mesh,
                      found.message.empty() ? found.row.method : found.message);
    return std::nullopt;
  }
  refined.load = *found.row.fold_load;
  if (found.fold) refined.point = std::move(found.fold);
  return refined;
}

std::optional<MeshErrorEstimate> richardson_estimate(const Scene& scene, double speed, const CoarseFold& coarse,
                                                     DistressSearchSettings settings, std::string& why,
                                                     const SearchProgress& progress) {
  const auto fine = refined_fold(scene, speed, coarse, std::move(settings), why, progress);
  if (!fine) return std::nullopt;
  return extrapolated(coarse.load, fine->load, mesh_name(fine->model->scene()));
}

RefinedFoldCurve::RefinedFoldCurve(const BearingModel& coarse, CurveParameter which, const FoldPoint& first)
    : RefinedFoldCurve(coarse, which, first.u, first.null_vector) {}

RefinedFoldCurve::RefinedFoldCurve(const BearingModel& coarse, CurveParameter which, std::span<const double> u,
                                   std::span<const double> null_guess)
    : coarse_(coarse), which_(which) {
  const Scene fine = refined_mesh(coarse.scene());
  fine_ = coarse.on_mesh(fine.mesh.radial_nodes, fine.mesh.circumferential_nodes);
  mesh_ = mesh_name(fine);
  first_null_ = moved_direction(*fine_, coarse_, u, null_guess);
}

std::optional<MeshErrorEstimate> RefinedFoldCurve::at(double p, double load, std::span<const double> u, int kind,
                                                      std::string& why) {
  // The coarse model must stand at p: its state u is interpolated through its settings.
  if (coarse_.curve_parameter(which_) != p)
    throw InternalError("RefinedFoldCurve::at: the coarse model is not at the point's parameter");
  fine_->set_curve_parameter(which_, p);
  std::vector<double> guess;
  double guess_load = load;
  const bool follow = !last_fine_.empty();
  if (follow) {
    // The last refined fold, moved as the coarse curve moved.
    guess = moved_difference(*fine_, coarse_, u, last_coarse_);
    for (std::size_t k = 0; k < guess.size(); ++k) guess[k] += last_fine_[k];
    guess_load = last_fine_load_ + (load - last_coarse_load_);
  } else {
    guess = fine_->interpolated_from(coarse_, u);
  }
  // The border needs only a vector not orthogonal to the null vector: the last one found
  // (kept across a refused point), else the first fold's.
  // The bar needs the refined fold's load only, and to a small part of the coarse-to-fine
  // difference: a thousandth of it (as predicted, at least a thousandth of a percent of the load)
  // moves the bar by 0.1 % of itself.
  const double accuracy = 1e-3 * std::max(std::abs(guess_load - load), 1e-3 * load);
  const std::vector<double>& border = last_null_.empty() ? first_null_ : last_null_;
  std::optional<FoldPoint> fold = checked_fold(*fine_, guess, guess_load, border, load, kind, why, accuracy);
  // A fold followed from further back than the last point (a level a chain's points
  // need only now and then) may start outside Newton's reach: again from the coarse fold.
  if (!fold && follow)
    fold = checked_fold(*fine_, fine_->interpolated_from(coarse_, u), load, border, load, kind, why, accuracy);
  last_coarse_.assign(u.begin(), u.end());
  last_coarse_load_ = load;
  if (!fold) {
    last_fine_.clear();
    return std::nullopt;
  }
  last_fine_ = fold->u;
  last_null_ = fold->null_vector;
  last_fine_load_ = fold->lambda;
  return extrapolated(load, fold->lambda, mesh_);
}

std::optional<double> crossing_on_finer_mesh(const BearingModel& coarse, BearingModel& fine, LimitKind kind,
                                             std::pair<double, std::vector<double>>& state, double width,
                                             double load_end, std::string& why, double predicted, double& slope) {
  // The predicted load where given (within load_end), else, or where Newton fails there,
  // the coarse crossing's.
  std::vector<double> starts{state.first};
  if (predicted > 0.0 && std::min(predicted, load_end) != state.first)
    starts.insert(starts.begin(), std::min(predicted, load_end));
  double load = starts.front();
  std::vector<double> v;
  NewtonSettings newton = newton_settings(fine.scene());
  newton.max_iterations = 20;
  // At the coarse crossing the coarse margin is nought, so the refined one is the
  // meshes' difference in margin, about the slope times their crossings' difference in
  // load: settled to 1e-3 of itself it moves the refined crossing by 1e-3 of that
  // difference, the bar by 0.1 % (the same part as a state's bars: refine_state). At a
  // predicted crossing the margin is near nought too: there it needs settling only to
  // what moves the root by the secant's own settling (a fiftieth of the width, at the
  // coarse mesh's slope).
  double floor = 0.0;
  const OperatingLimits limits = OperatingLimits::of(fine.scene());
  newton.quantities.at = [&](std::span<const double> w) {
    return std::vector<double>{*state_margin(fine, w, kind, limits)};
  };
  newton.quantities.settled = [&](const NewtonSettings::QuantityReads& reads) {
    return settled_by_contraction(
        reads, [&](std::size_t, double margin) { return std::max(1e-3 * std::abs(margin), floor); });
  };
  KinsolNewton polish(fine);
  bool polished = false;
  for (std::size_t k = 0; k < starts.size() && !polished; ++k) {
    load = starts[k];
    floor = std::abs(slope) * 0.02 * width * load;
    v = fine.interpolated_from(coarse, state.second);
    fine.set_load(load);
    const NewtonReport rep = polish.solve(v, newton);
    polished = rep.converged;
    if (!polished)
      why = fmt::format("Newton on the refined mesh did not converge at {:.6g} N (the {} crossing): {}", load,
                        k + 1 < starts.size() ? "predicted" : "coarse", rep.message);
  }
  if (!polished) return std::nullopt;
  // The margin's slope along the refined branch at the start's load, from the branch's
  // tangent u_W = −J⁻¹F_W with the polish's last factors (a Jacobian one Newton step
  // from the state: its error only moves the secant's first step): with it the
  // secant's first step lands next to the crossing instead of walking towards it.
  // (None where the polish factored nothing, its start already converged: the secant
  // then walks from its own first guess.)
  double refined_slope = 0.0;
  if (polish.factorization().factored()) {
    std::vector<double> u_load(v.size());
    fine.parameter_derivative(v, u_load);
    polish.factorization().solve(u_load);
    const double dw = kInputStep * load;
    refined_slope = stencil_derivative(kCentred2, dw, [&](std::size_t k) {
      const double shift = kCentred2.offsets[k] * dw;
      fine.set_load(load + shift);
      return std::vector<double>{*state_margin(fine, moved_state(v, u_load, shift), kind, limits)};
    })[0];
    fine.set_load(load);
  }
  state = {load, std::move(v)};
  long solves = 0;
  // The secant's solves refactor the polish's Jacobian pattern: its symbolic analysis
  // (nested dissection on refined meshes, about 80 ms) is done once.
  const std::optional<double> w =
      crossing_near(fine, kind, state, refined_slope, width, load_end, solves, why, &polish, nullptr, true);
  slope = refined_slope;
  return w;
}

std::optional<MeshErrorEstimate> crossing_sequence(const BearingModel& coarse, LimitKind kind,
                                                   std::pair<double, std::vector<double>> state, double bracket_width,
                                                   double load_end, double tolerance, const FinerBearing& finer,
                                                   std::string& why) {
  // To a fifth of the tolerance where that is finer than the bracket: the crossing's
  // location then moves its bar by little.
  const double width = tolerance > 0.0 ? std::min(bracket_width, tolerance / 5.0) : bracket_width;
  MeshSequence sequence(coarse.scene(), state.first);
  const BearingModel* at = &coarse;
  std::string finest;
  double slope = 0.0;  // the last mesh's dmargin/dW at its crossing
  do {
    const Scene* next = sequence.next_mesh();
    if (!next) break;
    std::string step_why;
    std::optional<double> w;
    BearingModel* fine = nullptr;
    try {
      fine = &finer(*next);
      w = crossing_on_finer_mesh(*at, *fine, kind, state, width, load_end, step_why,
                                 next_mesh_value(sequence.loads()), slope);
    } catch (const InternalError&) {
      throw;  // a bug: no fallback may hide it
    } catch (const std::exception& e) {
      if (sequence.loads().size() < 2) throw;  // no estimate yet: the caller says why
      step_why = e.what();
    }
    if (!w) {
      if (sequence.loads().size() < 2) {
        why = step_why;
        return std::nullopt;
      }
      sequence.stop(fmt::format("the crossing on {} from the one on {} failed: {}", mesh_name(*next), finest,
                                step_why));
      break;
    }
    sequence.add(*w);
    at = fine;
    finest = mesh_name(*next);
  } while (tolerance > 0.0 && sequence.wants_more(tolerance));
  return sequence_estimate(sequence, tolerance, finest);
}

std::optional<MeshErrorEstimate> crossing_estimate(const BearingModel& coarse, BearingModel& fine, LimitKind kind,
                                                   double load, std::span<const double> u, double width,
                                                   double load_end, std::string& why) {
  std::pair<double, std::vector<double>> state{load, std::vector<double>(u.begin(), u.end())};
  double slope = 0.0;
  const std::optional<double> w = crossing_on_finer_mesh(coarse, fine, kind, state, width, load_end, why, 0.0, slope);
  if (!w) return std::nullopt;
  return extrapolated(load, *w, mesh_name(fine.scene()));
}

}  // namespace twb
