#include "study/uncertainty/failure_at_inputs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

#include "model/failure_margins.h"
#include "results/record_bytes.h"
#include "study/uncertainty/crossing_response.h"
#include "study/searches/failure_load.h"
#include "study/uncertainty/fold_response.h"
#include "study/uncertainty/input_neighbours.h"
#include "study/searches/move_in_steps.h"
#include "study/parallel/parallel.h"
#include "twb/error_family.h"
#include "twb/input_error.h"
#include "twb/scene/scene_inputs.h"
#include "twb/scene/scene_loader.h"

namespace twb {

namespace {

// The fold system's difference step along a move, as a fraction of it: the forward
// difference's truncation (ε of the move's bend) far below the prediction's own error
// (the move's square).
constexpr double kTangentStep = 1e-3;

// Newton from a predicted fold converges in a few iterations (quadratically from the
// prediction's O(|d|²) error); one that needs more is better spent on a shorter move.
constexpr int kFollowIterations = 12;

}  // namespace

// A bearing at inputs x with the criteria followed there settled on it.
struct FailureLoadAtInputs::Settled {
  std::vector<double> x;
  std::unique_ptr<BearingModel> model;
  std::optional<SettledFold> fold;
  std::vector<SettledCrossing> crossings;
  // W_fail and what sets it; from a search at x whose failure could not be settled
  // (distress by bisection alone), its row's load without a way to follow it.
  double load = std::numeric_limits<double>::infinity();
  std::string criterion;
  bool searched = false;
  std::optional<DistressRow> row;  // a search's at x

  // W_fail from what is settled.
  void set_failure() {
    load = std::numeric_limits<double>::infinity();
    if (fold && fold->load < load) {
      load = fold->load;
      criterion = "distress";
    }
    for (const SettledCrossing& c : crossings)
      if (c.load < load) {
        load = c.load;
        criterion = criterion_name(FailureCriterion::crossing(c.kind));
      }
  }
  // What a failure search on `model` found, each criterion settled to the solver's
  // tolerance. A failure it located that cannot be settled (distress by bisection): its
  // load, without a way to follow or differentiate it. The search locates each load to
  // its bracket width only, so a settled load above the search's by less than that is the
  // same failure, settled; one the search puts lower by more is another, unsettled.
  void take(const DistressSearch& found, double bracket_width, std::string& why) {
    if (found.fold && found.fold_proven) fold = settle_fold(*model, *found.fold, why);
    for (std::size_t c = 0; c < found.crossing_states.size(); ++c) {
      const auto& [at_load, u] = found.crossing_states[c];
      if (u.empty()) continue;
      if (std::optional<SettledCrossing> settled = settle_crossing(*model, kFailureCriteria[c], at_load, u, why))
        crossings.push_back(std::move(*settled));
    }
    set_failure();
    if (found.row.failure_load && *found.row.failure_load < load * (1.0 - bracket_width)) {
      load = *found.row.failure_load;
      criterion = found.row.criterion ? criterion_name(*found.row.criterion) : "distress";
      fold.reset();
      crossings.clear();
    }
  }
  // Whether a later move can start from it: a fold or a crossing settled.
  bool followable() const { return fold || !crossings.empty(); }
  // The state where W_fail is set.
  std::span<const double> failing_state() const {
    for (const SettledCrossing& c : crossings)
      if (c.load == load) return c.u;
    return fold->u;
  }
};

FailureLoadAtInputs::FailureLoadAtInputs(const Scene& scene, std::vector<std::string> paths, std::vector<double> scales,
                                         DistressSearchSettings search, int threads)
    // The bearing's scene without its study: every bearing at other inputs reads it again,
    // and a study read again would check its own inputs round the moved ones.
    : scene_(bearing_scene(scene)),
      paths_(std::move(paths)),
      scales_(std::move(scales)),
      search_(std::move(search)),
      threads_(threads) {
  search_.march_past_distress = false;
}

FailureLoadAtInputs::~FailureLoadAtInputs() = default;

std::unique_ptr<FailureLoadAtInputs::Settled> FailureLoadAtInputs::bearing_at(std::span<const double> x,
                                                                             std::string& why) const {
  auto s = std::make_unique<Settled>();
  s->x.assign(x.begin(), x.end());
  s->model = model_at(x, why);
  return s->model ? std::move(s) : nullptr;
}

std::unique_ptr<BearingModel> FailureLoadAtInputs::model_at(std::span<const double> x, std::string& why) const {
  std::vector<std::pair<std::string, double>> set;
  for (std::size_t i = 0; i < paths_.size(); ++i) set.emplace_back(paths_[i], x[i]);
  try {
    return std::make_unique<BearingModel>(with_inputs(scene_, set));
  } catch (const InputError& e) {
    why = e.message();
    return nullptr;
  }
}

const DistressSearch* FailureLoadAtInputs::search_at(std::span<const double> x, const SearchProgress& progress,
                                                     std::string& why) {
  std::unique_ptr<Settled> s = bearing_at(x, why);
  if (!s) return nullptr;
  s->searched = true;
  first_x_.assign(x.begin(), x.end());
  // Its cool branch's states are where the states at an operating load start (operate_at).
  DistressSearchSettings settings = search_;
  settings.keep_state_vectors = true;
  first_search_ = search_distress(*s->model, settings, progress);
  ++searches_;
  s->take(first_search_, search_.bracket_width, why);
  remember(std::move(s));
  return &first_search_;
}

std::unique_ptr<FailureLoadAtInputs::Settled> FailureLoadAtInputs::settle_once(const Settled& from,
                                                                              std::span<const double> x,
                                                                              std::string& why) const {
  std::unique_ptr<Settled> s = bearing_at(x, why);
  if (!s) return nullptr;
  if (from.fold) {
    // Newton on the fold system from the fold predicted along the move's tangent, else
    // from the settled fold itself.
    FoldPoint start;
    start.u = from.fold->u;
    start.lambda = from.fold->load;
    start.null_vector = from.fold->null_vector;
    std::vector<double> ahead(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) ahead[i] = from.x[i] + kTangentStep * (x[i] - from.x[i]);
    std::string unused;
    const std::unique_ptr<BearingModel> at_from = model_at(from.x, unused), at_ahead = model_at(ahead, unused);
    if (at_from && at_ahead)
      if (std::optional<FoldPoint> predicted = predicted_fold(*at_from, *at_ahead, kTangentStep, *from.fold);
          predicted && predicted->lambda > 0.0)  // (a long move's line may cross zero load)
        start = std::move(*predicted);
    s->fold = settle_fold(*s->model, start, why, kFollowIterations);
    if (!s->fold) return nullptr;
    // A fold where the load is least is the hot branch's recovery, not distress.
    if (!(s->fold->curvature > 0.0)) {
      why = fmt::format("Newton from the fold at {:.6g} N reached the hot branch's fold at {:.6g} N, not distress",
                        from.fold->load, s->fold->load);
      return nullptr;
    }
  }
  for (const SettledCrossing& f : from.crossings) {
    std::optional<SettledCrossing> settled = settle_crossing(*s->model, f.kind, f.load, f.u, why);
    if (!settled) return nullptr;
    s->crossings.push_back(std::move(*settled));
  }
  s->set_failure();
  return s;
}

std::unique_ptr<FailureLoadAtInputs::Settled> FailureLoadAtInputs::walk(const Settled& from, std::span<const double> x,
                                                                       std::string& why) const {
  // Newton reaches a few percent of the load from a settled point: the move from `from`
  // to x is walked in steps.
  std::unique_ptr<Settled> here;
  const Settled* last = &from;
  std::vector<double> at(x.size());
  const bool made = move_in_steps(kLeastStep, [&](double, double reached) {
    for (std::size_t i = 0; i < x.size(); ++i) at[i] = from.x[i] + reached * (x[i] - from.x[i]);
    std::string failed;
    std::unique_ptr<Settled> next;
    try {
      next = settle_once(*last, at, failed);
    } catch (const InternalError&) {
      throw;  // a bug: no shorter step may hide it
    } catch (const std::exception& e) {
      failed = e.what();  // a load or state a step cannot take: a shorter one may
    }
    if (!next) {
      why = failed;
      return failed.empty() ? StepTaken::never : StepTaken::no;
    }
    if (here && keeping_) remember(std::move(here));
    here = std::move(next);
    last = here.get();
    return StepTaken::yes;
  });
  return made ? std::move(here) : nullptr;
}

void FailureLoadAtInputs::remember(std::unique_ptr<Settled> s) const {
  s->model.reset();
  const std::lock_guard<std::mutex> hold(anchors_lock_);
  anchors_.push_back(std::move(s));
}

std::unique_ptr<FailureLoadAtInputs::Settled> FailureLoadAtInputs::searched_at(std::span<const double> x,
                                                                              std::string& why) const {
  std::unique_ptr<Settled> s = bearing_at(x, why);
  if (!s) return nullptr;
  s->searched = true;
  const DistressSearch found = search_distress(*s->model, search_, {});
  ++searches_;
  s->row = found.row;
  if (found.failed) {
    // No steady state even at the light load: the bearing fails below load_start, at
    // any load the study asks about.
    s->load = 0.0;
    s->criterion = "no steady state at " + std::to_string(search_.load_start) + " N";
    return s;
  }
  s->take(found, search_.bracket_width, why);
  return s;
}

std::unique_ptr<FailureLoadAtInputs::Settled> FailureLoadAtInputs::from_nearest(std::span<const double> x,
                                                                               std::string& why,
                                                                               bool& refused) const {
  const Settled* nearest = nullptr;
  double least = std::numeric_limits<double>::infinity();
  std::vector<std::shared_ptr<const Settled>> anchors;
  {
    const std::lock_guard<std::mutex> hold(anchors_lock_);
    anchors = anchors_;
  }
  for (const std::shared_ptr<const Settled>& a : anchors) {
    if (!a->followable()) continue;
    double d = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) d += std::pow((x[i] - a->x[i]) / scales_[i], 2);
    if (d < least) least = d, nearest = a.get();
  }
  if (!nearest) return nullptr;
  std::string moved;
  std::unique_ptr<Settled> s;
  if (least == 0.0 && nearest->crossings.empty()) {
    // A settled fold's own inputs (FORM's start at the medians the search ran at): its
    // fold, on a bearing built again.
    s = bearing_at(x, why);
    if (!s) {
      refused = true;
      return nullptr;
    }
    s->fold = nearest->fold;
    s->set_failure();
  } else {
    s = walk(*nearest, x, moved);
  }
  if (s && !crosses_unfollowed(*s)) return s;
  return nullptr;
}

std::unique_ptr<FailureLoadAtInputs::Settled> FailureLoadAtInputs::settled_at(std::span<const double> x,
                                                                             std::string& why) const {
  bool refused = false;
  if (std::unique_ptr<Settled> s = from_nearest(x, why, refused)) return s;
  if (refused) return nullptr;
  // (Outside an input's range the search's bearing is refused too, with the reason.)
  return searched_at(x, why);
}

void FailureLoadAtInputs::operate_at(double load, std::span<const double> towards) {
  operating_.reset();
  // Where the search's cool branch ends below the load there is no state there to hold.
  const DistressSearch& found = first_search_;
  if (found.row.distress_load && *found.row.distress_load <= load) return;
  if (found.row.fold_load && *found.row.fold_load <= load) return;
  auto states = std::make_unique<OperatingStates>(
      load, scales_, [this](std::span<const double> x, std::string& why) { return model_at(x, why); });
  // The first search's cool state nearest the load.
  const std::size_t cool = std::min(found.cool_states, found.state_vectors.size());
  std::optional<std::size_t> from;
  for (std::size_t i = 0; i < cool; ++i)
    if (!from || std::abs(found.states[i].state.load - load) < std::abs(found.states[*from].state.load - load)) from = i;
  if (!from) return;
  try {
    std::string why;
    if (!states->hold_from_branch(first_x_, found.states[*from].state.load, found.state_vectors[*from], why)) return;
    states->hold_towards(towards);
  } catch (const InternalError&) {
    throw;  // a bug: no fallback may hide it
  } catch (const std::exception&) {
    return;  // no state to start from: every sample by its failure load
  }
  operating_ = std::move(states);
}

void FailureLoadAtInputs::hold_later(const Sample& sample, BearingModel& model, std::span<const double> x,
                                     double load, const std::vector<double>& u) const {
  // A state only the next batches start from: where it cannot be described, none is held.
  try {
    model.set_load(load);
    operating_->hold_later(sample.number, OperatingStates::state_of(model, x, u));
  } catch (const InternalError&) {
    throw;
  } catch (const std::exception&) {
  }
}

void FailureLoadAtInputs::hold_samples() {
  if (operating_) operating_->hold_those_waiting();
  const std::lock_guard<std::mutex> hold(told_lock_);
  told_.clear();
}

void FailureLoadAtInputs::note(const std::optional<Sample>& sample, Told how) const {
  if (!sample) return;
  const std::lock_guard<std::mutex> hold(told_lock_);
  told_[sample->number] = how;
}

void FailureLoadAtInputs::write_sample_report(RecordWriter& out, std::uint64_t sample) const {
  Told how = Told::by_failure_load;
  {
    const std::lock_guard<std::mutex> hold(told_lock_);
    if (const auto it = told_.find(sample); it != told_.end()) how = it->second;
  }
  out(how), out(operating_ != nullptr);
  if (operating_) operating_->write_waiting(out, sample);
}

void FailureLoadAtInputs::take_sample_report(RecordReader& in, std::uint64_t sample) {
  Told how = Told::by_failure_load;
  bool operating = false;
  in(how), in(operating);
  if (std::uint8_t(how) > std::uint8_t(Told::by_search)) in.damaged();
  if (how == Told::by_state) ++judged_by_state_;
  if (how == Told::by_search) ++searches_;
  note(Sample{sample, true}, how);
  if (operating) {
    if (!operating_) throw std::runtime_error(fmt::format("sample {}'s report holds a state where none is held", sample));
    operating_->take_waiting(in, false);
  }
}

void FailureLoadAtInputs::write_batch_states(RecordWriter& out) const {
  out(operating_ != nullptr);
  if (operating_) operating_->write_waiting(out);
}

void FailureLoadAtInputs::take_batch_states(RecordReader& in) {
  bool operating = false;
  in(operating);
  if (operating != (operating_ != nullptr)) in.damaged();
  if (operating_) operating_->take_waiting(in, true);
}

std::optional<bool> FailureLoadAtInputs::fails_at(std::span<const double> x, double load, std::string& why,
                                                  std::optional<Sample> sample) const {
  // By the state at the load where it can be reached: on FORM's safe side from the states
  // held at the load, then from those below it; on its failing side from those below it
  // only (the states at the load seldom reach a sample there, whose cool branch most often
  // ends below the load: trying them cost more than the few they tell).
  const bool by_state = operating_ && operating_->load() == load;
  if (by_state) {
    const bool safe_side = !sample || sample->likely_safe;
    std::optional<OperatingStates::Verdict> v = operating_->judge(x, safe_side);
    if (!v && safe_side) v = operating_->judge(x, false);
    if (v) {
      ++judged_by_state_;
      note(sample, Told::by_state);
      if (sample) operating_->hold_later(sample->number, v->state);
      return v->fails;
    }
  }
  // Else by the failure load, followed from a settled point or searched.
  bool refused = false;
  if (const std::unique_ptr<Settled> s = from_nearest(x, why, refused)) {
    // A crossing at most the load: its state is one later samples' states start from.
    if (by_state && sample && s->load <= load)
      for (const SettledCrossing& c : s->crossings)
        if (c.load == s->load) hold_later(*sample, *s->model, x, c.load, c.u);
    return s->load <= load;
  }
  if (refused) return std::nullopt;
  // The search alone answers, with the loads it located (a sample's state is no point to
  // follow from: nothing is settled). It ends ten bracket widths above `load`: a failure
  // load between them is located as any other (and lies above `load`), and none up to
  // there means none at `load`.
  const std::unique_ptr<Settled> s = bearing_at(x, why);
  if (!s) return std::nullopt;
  DistressSearchSettings settings = search_;
  settings.load_end = std::clamp(load * (1.0 + 10.0 * search_.bracket_width), search_.load_start, search_.load_end);
  const DistressSearch found = search_distress(*s->model, settings, {});
  ++searches_;
  note(sample, Told::by_search);
  // No steady state even at the light load: the bearing fails below load_start.
  if (found.failed) return true;
  const bool fails = found.row.failure_load && *found.row.failure_load <= load;
  // Failing by a crossing: its state is one later samples' states start from.
  // (its state at the crossing, or on the cool branch below it where the crossing lies
  // next to the fold: failure_load.cpp).
  if (by_state && sample && fails && found.row.criterion && !found.row.criterion->distress)
    if (const std::optional<std::size_t> c = criterion_index(found.row.criterion->limit);
        c && *c < found.crossing_states.size())
      if (const auto& [at_load, u] = found.crossing_states[*c]; !u.empty() && at_load <= load)
        hold_later(*sample, *s->model, x, at_load, u);
  return fails;
}

bool FailureLoadAtInputs::crosses_unfollowed(const Settled& s) const {
  const FailureMargins margins(
      LimitValues::of(s.model->describe(s.failing_state()), s.model->scene().effects.thermal),
      OperatingLimits::of(s.model->scene()));
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c)
    if (margins.past(c) && std::none_of(s.crossings.begin(), s.crossings.end(),
                                        [&](const SettledCrossing& x) { return x.kind == kFailureCriteria[c]; }))
      return true;
  return false;
}

std::optional<FailureLoadAtInputs::Followed> FailureLoadAtInputs::follow(const Followed* from,
                                                                         std::span<const double> x,
                                                                         std::string& why) const {
  std::unique_ptr<Settled> s;
  if (from && from->point && from->point->followable()) {
    std::string moved;
    s = walk(*from->point, x, moved);
    if (s && crosses_unfollowed(*s)) s.reset();
  }
  if (!s) s = searched_at(x, why);  // (refused, with the reason, outside an input's range)
  if (!s) return std::nullopt;
  Followed out;
  out.failure.load = s->load;
  out.failure.criterion = s->criterion;
  out.failure.searched = s->searched;
  if (s->fold) out.fold = s->fold->load;
  for (const SettledCrossing& c : s->crossings) out.crossings.emplace_back(c.kind, c.load);
  out.search_row = s->row;
  // A move starts from the settled states and builds its own bearings; the crossings'
  // factors serve gradients only: a map of many points keeps neither.
  s->model.reset();
  for (SettledCrossing& c : s->crossings) c.lu.reset();
  out.point = std::move(s);
  return out;
}

std::optional<FailureAtInputs> FailureLoadAtInputs::at(std::span<const double> x, bool gradient, std::string& why) const {
  std::unique_ptr<Settled> s = settled_at(x, why);
  if (!s) return std::nullopt;
  FailureAtInputs out;
  out.load = s->load;
  out.criterion = s->criterion;
  out.searched = s->searched;
  if (!gradient) {
    if (keeping_ && s->followable()) remember(std::move(s));
    return out;
  }
  if (!std::isfinite(s->load)) {
    why = fmt::format("no failure up to {:.6g} N there, so no gradient", search_.load_end);
    return std::nullopt;
  }
  if (!s->followable()) {
    why = "the failure there was located by bisection only (no fold to follow), so no gradient";
    return std::nullopt;
  }
  const SettledCrossing* crossing = nullptr;
  for (const SettledCrossing& c : s->crossings)
    if (c.load == s->load) crossing = &c;
  out.gradient.assign(paths_.size(), 0.0);
  std::vector<std::string> failed(paths_.size());
  std::mutex solve_lock;
  run_in_parallel(paths_.size(), threads_, [&](std::size_t i) {
    try {
      // Second order: its δ² truncation (10⁻⁸ relative) is far below FORM's tolerance.
      InputNeighbours nb = input_neighbours(*s->model, scene_input(s->model->scene(), paths_[i]), 2);
      out.gradient[i] = crossing ? crossing_load_derivative(nb, *crossing, solve_lock) : fold_load_derivative(nb, *s->fold);
      if (!std::isfinite(out.gradient[i])) failed[i] = paths_[i] + ": the derivative is not finite";
    } catch (const InternalError&) {
      throw;
    } catch (const std::exception& e) {
      failed[i] = paths_[i] + ": " + e.what();
    }
  });
  for (const std::string& f : failed)
    if (!f.empty()) {
      why = "W_fail's derivative in " + f;
      return std::nullopt;
    }
  if (keeping_) remember(std::move(s));
  return out;
}

void FailureLoadAtInputs::keep(std::span<const double> x) {
  std::string why;
  if (std::unique_ptr<Settled> s = settled_at(x, why); s && s->followable()) remember(std::move(s));
}

}  // namespace twb
