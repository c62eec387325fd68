#include "study/searches/operating_states.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "model/failure_margins.h"
#include "results/record_bytes.h"
#include "solver/kinsol_newton.h"
#include "solver/linear_stability.h"
#include "study/searches/move_in_steps.h"
#include "study/study_support.h"
#include "twb/error_family.h"

namespace twb {

namespace {

// A move Newton reaches in a few undamped steps from a state of the same branch; one that
// needs more is better walked in shorter steps.
constexpr int kMoveIterations = 12;
// The hottest film node's rise above the ambient changes by at most this factor a step:
// the hot branch's rises at the same load are many times the cool one's.
constexpr double kLargestRiseFactor = 2.0;
// The shortest step of a sample's walk tried before it is given up (for a failure load,
// which costs about as much as three failed steps), and of the way to the design point,
// which serves every sample.
constexpr double kLeastSampleStep = 0.125;
constexpr double kLeastStep = 1.0 / 32;
// Up the branch in load (a sample on the failing side, from a state below the load): the
// cool branch's margins change by a few percent of themselves over such a step.
constexpr double kLoadStep = 0.05;

// A waiting state's fields but its sample, for writing and reading alike (S is const when
// writing).
template <class A, class S>
void waiting_fields(A& a, S& s) {
  a(s.x), a(s.u), a(s.load), a(s.rise), a(s.past_limit);
}

}  // namespace

OperatingStates::OperatingStates(double load, std::vector<double> scales, BearingAt bearing_at)
    : load_(load), scales_(std::move(scales)), bearing_at_(std::move(bearing_at)) {}

std::shared_ptr<const OperatingStates::State> OperatingStates::state_of(const BearingModel& model,
                                                                       std::span<const double> x,
                                                                       std::vector<double> u) {
  auto s = std::make_shared<State>();
  s->x.assign(x.begin(), x.end());
  s->u = std::move(u);
  s->load = model.load();
  const BearingState b = model.describe(s->u);
  s->rise = b.max_film_temperature - model.scene().operating.ambient;
  const OperatingLimits limits = OperatingLimits::of(model.scene());
  s->past_limit = FailureMargins(LimitValues::of(b, model.scene().effects.thermal), limits).first_past().has_value();
  return s;
}

std::shared_ptr<const OperatingStates::State> OperatingStates::settle_near(BearingModel& model,
                                                                          std::span<const double> x,
                                                                          const State& from) const {
  std::vector<double> u = from.u;
  NewtonSettings newton = newton_settings(model.scene());
  newton.max_iterations = kMoveIterations;
  newton.line_search = false;
  KinsolNewton solver(model);
  if (!solver.solve(u, newton).converged) return nullptr;
  std::shared_ptr<const State> s = state_of(model, x, std::move(u));
  if (!(s->rise <= kLargestRiseFactor * from.rise && from.rise <= kLargestRiseFactor * s->rise)) return nullptr;
  // The unstable middle branch lies next to the cool one near the fold, within the rise's
  // bound: a state shown unstable (with the factors Newton ended on) is not the cool one.
  // (Without the thermal effect there is neither: nothing has a capacity.)
  if (!model.scene().effects.thermal) return s;
  SparseLu& factors = solver.factorization();
  if (!factors.factored()) {  // (a start already converged: Newton factored nothing)
    std::vector<double> residual(std::size_t(model.size())), jacobian(std::size_t(model.pattern().nnz()));
    model.evaluate(s->u, residual, jacobian);
    if (!factors.factor(jacobian)) return nullptr;
  }
  if (linear_stability(model, factors).verdict == Stability::unstable) return nullptr;
  return s;
}

bool OperatingStates::hold_from_branch(std::span<const double> x, double from_load, std::span<const double> u,
                                       std::string& why) {
  std::unique_ptr<BearingModel> model = bearing_at_(x, why);
  if (!model) return false;
  model->set_load(from_load);
  std::shared_ptr<const State> last = state_of(*model, x, std::vector<double>(u.begin(), u.end()));
  // Along the branch in load, in steps as a walk's.
  const bool made = move_in_steps(kLeastStep, [&](double, double reached) {
    model->set_load(reached < 1.0 ? from_load + reached * (load_ - from_load) : load_);
    std::shared_ptr<const State> next = settle_near(*model, x, *last);
    if (!next) return StepTaken::no;
    last = std::move(next);
    return StepTaken::yes;
  });
  if (!made) {
    why = "Newton could not follow the branch to the operating load";
    return false;
  }
  const std::lock_guard<std::mutex> hold(lock_);
  held_.push_back(std::move(last));
  return true;
}

std::vector<std::shared_ptr<const OperatingStates::State>> OperatingStates::walk(
    const State& from, std::span<const double> x, bool all, double least,
    std::unique_ptr<BearingModel>* bearing) const {
  std::vector<std::shared_ptr<const State>> way;
  const State* last = &from;
  std::vector<double> at(x.size());
  move_in_steps(least, [&](double, double reached) {
    for (std::size_t i = 0; i < x.size(); ++i) at[i] = reached < 1.0 ? from.x[i] + reached * (x[i] - from.x[i]) : x[i];
    std::string why;
    std::shared_ptr<const State> next;
    std::unique_ptr<BearingModel> model;
    try {
      if ((model = bearing_at_(at, why))) {
        model->set_load(from.load);
        next = settle_near(*model, at, *last);
      }
    } catch (const InternalError&) {
      throw;  // a bug: no shorter step may hide it
    } catch (const std::exception&) {
      // a state a step cannot take: a shorter one may
    }
    // Inputs the scene refuses: no shorter step reaches them either.
    if (!model) return StepTaken::never;
    if (!next) return StepTaken::no;
    if (!all) way.clear();
    way.push_back(std::move(next));
    last = way.back().get();
    if (bearing) *bearing = std::move(model);
    return StepTaken::yes;
  });
  return way;
}

std::shared_ptr<const OperatingStates::State> OperatingStates::past_limit_up_to_load(BearingModel& model,
                                                                                    const State& from) const {
  // Up the branch in load steps of at most kLoadStep, each halved where Newton fails
  // (down to an eighth of it).
  std::shared_ptr<const State> last;
  StepLength step(kLoadStep, kLoadStep / 8, 1.0);
  while (!(last ? last->past_limit : from.past_limit)) {
    const double at = (last ? *last : from).load;
    if (at >= load_) return last;  // the operating load reached, every margin positive
    const double next_load = std::min(load_, at * (1.0 + step.value()));
    model.set_load(next_load);
    std::shared_ptr<const State> next = settle_near(model, from.x, last ? *last : from);
    if (!next) {
      if (!step.halve()) return nullptr;
      continue;
    }
    last = std::move(next);
  }
  return last;
}

std::shared_ptr<const OperatingStates::State> OperatingStates::nearest(std::span<const double> x,
                                                                      bool at_load) const {
  const std::lock_guard<std::mutex> hold(lock_);
  std::shared_ptr<const State> best;
  double least = std::numeric_limits<double>::infinity();
  for (const std::shared_ptr<const State>& s : held_) {
    if (at_load != (s->load == load_)) continue;
    double d = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) d += std::pow((x[i] - s->x[i]) / scales_[i], 2);
    if (d < least) least = d, best = s;
  }
  return best;
}

void OperatingStates::hold_towards(std::span<const double> x) {
  const std::shared_ptr<const State> from = nearest(x, true);
  if (!from) return;
  std::vector<std::shared_ptr<const State>> way = walk(*from, x, true, kLeastStep);
  const std::lock_guard<std::mutex> hold(lock_);
  held_.insert(held_.end(), way.begin(), way.end());
}

std::optional<OperatingStates::Verdict> OperatingStates::judge(std::span<const double> x, bool at_load) const {
  const std::shared_ptr<const State> from = nearest(x, at_load);
  if (!from) return std::nullopt;
  std::unique_ptr<BearingModel> bearing;
  std::vector<std::shared_ptr<const State>> way = walk(*from, x, false, kLeastSampleStep, &bearing);
  if (way.empty() || !std::equal(x.begin(), x.end(), way.back()->x.begin(), way.back()->x.end())) return std::nullopt;
  std::shared_ptr<const State> s = way.back();
  // Below the operating load only a negative margin tells: up the branch until one is.
  if (!s->past_limit && s->load < load_) {
    try {
      s = past_limit_up_to_load(*bearing, *s);
    } catch (const InternalError&) {
      throw;  // a bug: no failure search may hide it
    } catch (const std::exception&) {
      s = nullptr;  // a load the branch cannot take
    }
    if (!s) return std::nullopt;
  }
  return Verdict{s->past_limit, s};
}

void OperatingStates::hold_later(std::uint64_t sample, std::shared_ptr<const State> s) {
  const std::lock_guard<std::mutex> hold(lock_);
  waiting_[sample] = std::move(s);
}

void OperatingStates::write_waiting(RecordWriter& out, std::optional<std::uint64_t> only) const {
  const std::lock_guard<std::mutex> hold(lock_);
  out.count(only ? waiting_.count(*only) : waiting_.size());
  for (const auto& [sample, s] : waiting_) {
    if (only && sample != *only) continue;
    out(sample);
    waiting_fields(out, *s);
  }
}

void OperatingStates::take_waiting(RecordReader& in, bool instead) {
  std::map<std::uint64_t, std::shared_ptr<const State>> taken;
  for (std::size_t k = in.count(); k > 0; --k) {
    std::uint64_t sample = 0;
    in(sample);
    auto s = std::make_shared<State>();
    waiting_fields(in, *s);
    if (s->x.size() != scales_.size()) in.damaged();
    taken[sample] = std::move(s);
  }
  const std::lock_guard<std::mutex> hold(lock_);
  if (instead) waiting_.clear();
  for (auto& [sample, s] : taken) waiting_[sample] = std::move(s);
}

std::size_t OperatingStates::held() const {
  const std::lock_guard<std::mutex> hold(lock_);
  return held_.size();
}

void OperatingStates::hold_those_waiting() {
  const std::lock_guard<std::mutex> hold(lock_);
  for (auto& [sample, s] : waiting_) held_.push_back(std::move(s));
  waiting_.clear();
}

}  // namespace twb
