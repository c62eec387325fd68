#include "study/uncertainty/reliability.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <numeric>

#include <fmt/format.h>

#include "results/record_bytes.h"
#include "scene/scene_names.h"
#include "study/uncertainty/failure_at_inputs.h"
#include "study/searches/failure_load.h"
#include "study/uncertainty/first_order_reliability.h"
#include "study/uncertainty/importance_sampling.h"
#include "study/parallel/search_scheduler.h"
#include "scene/input_distribution.h"
#include "study/study_support.h"
#include "twb/error_family.h"
#include "twb/results/run_axes.h"

namespace twb {

namespace {

// Where the inputs stand at a design point, one row each.
void add_design_point(StudyOutcome& out, const char* method, const DesignPoint& p,
                      const std::vector<UncertainInput>& inputs) {
  std::vector<DesignPointRow>& rows = out.own_part<ReliabilityOutcome>().design_points;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const UncertainInput& in = inputs[i];
    DesignPointRow& r = rows.emplace_back();
    r.method = method;
    r.load = p.load;
    r.probability = p.probability;
    r.parameter = in.path;
    r.parameter_unit = in.unit;
    r.distribution = std::string(scene_io::kInputDistributions.name(in.distribution));
    if (has_mean_and_sd(in.distribution)) r.mean = in.mean, r.sd = in.sd;
    if (has_bounds(in.distribution)) r.lower = in.lower, r.upper = in.upper;
    r.design_value = input_at(in, p.u[i]);
    r.u = p.u[i];
    r.alpha = p.alpha[i];
    r.importance = p.alpha[i] * p.alpha[i];
    r.derivative = p.gradient[i] / input_slope(in, p.u[i]);
  }
}

// "geometry.gear.tilt 0.000731 rad (importance 0.81), ...", by importance.
std::string design_point_words(const DesignPoint& p, const std::vector<UncertainInput>& inputs) {
  std::vector<std::size_t> order(inputs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(p.alpha[a]) > std::abs(p.alpha[b]);
  });
  std::string words;
  for (std::size_t i : order)
    words += fmt::format("{}{} {:.4g}{} (importance {:.2f})", words.empty() ? "" : ", ", inputs[i].path,
                         input_at(inputs[i], p.u[i]), inputs[i].unit == "1" ? "" : " " + inputs[i].unit,
                         p.alpha[i] * p.alpha[i]);
  return words;
}

// A batch's samples through `scheduler` (MPI ranks): each rank judges its share, whose
// verdicts, reasons and states arrive at the rank that takes the results; that rank then
// gives every rank the batch's verdicts and its states to hold, so that every rank holds
// the same states, in sample order, and draws the same next batch.
SpreadBatch spread_over(SearchScheduler& scheduler, int threads, FailureLoadAtInputs& failure, std::mutex& why_lock,
                        std::map<std::uint64_t, std::string>& unresolved_why) {
  return [&scheduler, threads, &failure, &why_lock, &unresolved_why](std::uint64_t first, std::size_t count,
                                                                     const JudgeSample& judge) {
    std::vector<std::optional<bool>> verdicts(count);
    std::vector<std::size_t> todo(count);
    for (std::size_t k = 0; k < count; ++k) todo[k] = first + k;
    SearchScheduler::Work work;
    work.run_here = [&](std::size_t i) { verdicts[i - first] = judge(i); };
    // A sample's message: its verdict, why it has none, and the sample's report.
    work.run_for_another = [&](std::size_t i) {
      const std::optional<bool> v = judge(i);
      std::string why;
      if (!v) {
        const std::lock_guard<std::mutex> hold(why_lock);
        why = unresolved_why[i];
      }
      RecordWriter out;
      out(v), out(why);
      failure.write_sample_report(out, i);
      return out.take();
    };
    work.arrived = [&](std::size_t i, const std::string& bytes) {
      RecordReader in(bytes, fmt::format("sample {}'s message", i));
      if (i < first || i >= first + count) in.damaged();
      std::optional<bool> v;
      std::string why;
      in(v), in(why);
      verdicts[i - first] = v;
      if (!v) {
        const std::lock_guard<std::mutex> hold(why_lock);
        unresolved_why[i] = why;
      }
      failure.take_sample_report(in, i);
      in.finish();
    };
    scheduler.run(todo, threads, work);
    // The batch's verdicts and the states to hold.
    if (scheduler.takes_results()) {
      RecordWriter out;
      out(verdicts);
      failure.write_batch_states(out);
      std::string batch = out.take();
      scheduler.share(batch);
    } else {
      std::string batch;
      scheduler.share(batch);
      RecordReader in(batch, "a batch's message");
      in(verdicts);
      if (verdicts.size() != count) in.damaged();
      failure.take_batch_states(in);
      in.finish();
    }
    failure.hold_samples();
    return verdicts;
  };
}

// The inputs at standard-normal coordinates u.
std::vector<double> inputs_at_coordinates(const std::vector<UncertainInput>& inputs, std::span<const double> u) {
  std::vector<double> x(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) x[i] = input_at(inputs[i], u[i]);
  return x;
}

// The Monte Carlo check round FORM's design point, its row and summary; false on the
// ranks of an MPI job that leave the rest to the one that takes the results.
bool importance_sampling_check(FailureLoadAtInputs& failure, const DesignPoint& form,
                               const std::vector<UncertainInput>& inputs, double load, double speed,
                               const ReliabilitySettings& st,
                               int threads, SearchScheduler* scheduler, const ProgressReport& progress,
                               StudyOutcome& out) {
  const auto inputs_at = [&](std::span<const double> u) { return inputs_at_coordinates(inputs, u); };
  if (progress) progress(fmt::format("reliability: importance sampling to a coefficient of variation of {:.3g}", st.sampling_cov));
  // Why each sample that could not be told was not (the first, by number, is reported).
  std::mutex why_lock;
  std::map<std::uint64_t, std::string> unresolved_why;
  // A sample asks only whether the bearing fails at the operating load: a search it
  // needs ends just above that load (FailureLoadAtInputs::fails_at).
  // Most samples are told by their state at the load, moved from the states held at the
  // load (OperatingStates): the first search's, the way to the design point, and the
  // samples of the batches before.
  failure.operate_at(load, inputs_at(form.u));
  const FailureIndicator fails = [&](std::uint64_t sample, std::span<const double> u) -> std::optional<bool> {
    std::string why;
    std::optional<bool> failed;
    try {
      // FORM's safe side: u·u* < β².
      const bool safe_side = std::inner_product(u.begin(), u.end(), form.u.begin(), 0.0) < form.beta * form.beta;
      failed = failure.fails_at(inputs_at(u), load, why, FailureLoadAtInputs::Sample{sample, safe_side});
    } catch (const InternalError&) {
      throw;  // a bug: no sample may hide it
    } catch (const std::exception& e) {
      why = e.what();  // one sample's, not the study's
    }
    if (!failed) {
      const std::lock_guard<std::mutex> hold(why_lock);
      unresolved_why[sample] = why;
    }
    return failed;
  };
  SamplingSettings sampling;
  sampling.cov = st.sampling_cov;
  sampling.max_samples = st.max_samples;
  sampling.min_samples = std::min(100, st.max_samples);
  sampling.seed = std::uint64_t(st.seed);
  sampling.threads = threads;
  const SpreadBatch spread = scheduler ? spread_over(*scheduler, threads, failure, why_lock, unresolved_why)
                                       : batch_on_threads(threads, [&] { failure.hold_samples(); });
  // Every rank of an MPI job holds the same states after each batch (spread_over): its
  // progress lines say so.
  const SamplingEstimate e = importance_sampling(fails, form.u, sampling, spread, [&](const SamplingEstimate& now) {
    if (progress)
      progress(fmt::format("reliability: {} samples, P_f = {:.4g}, coefficient of variation {:.3g}; {} states held",
                           now.samples, now.probability, now.cov, failure.states_held()));
  });
  // The other ranks of an MPI job leave the rest to the one that takes the results.
  if (scheduler && !scheduler->takes_results()) return false;
  const std::string first_why = unresolved_why.empty() ? std::string() : unresolved_why.begin()->second;
  ReliabilityRow& mc = out.own_part<ReliabilityOutcome>().rows.emplace_back();
  mc.method = "monte_carlo";
  mc.load = load;
  mc.speed = speed;
  mc.probability = e.probability;
  if (e.failures > 0) mc.cov = e.cov;
  mc.low = e.low;
  mc.high = e.high;
  mc.samples = e.samples;
  mc.failures = e.failures;
  mc.unresolved = e.unresolved;
  mc.evaluations = e.samples;  // one each, wherever judged
  // Unresolved samples are left out, and they need not be like the others.
  mc.converged = e.reached && e.unresolved == 0;
  out.summary.push_back(fmt::format(
      "reliability: Monte Carlo (importance sampling round the design point): P_f = {:.3g}, 95 % interval [{:.3g}, "
      "{:.3g}], coefficient of variation {:.3g} from {} samples ({} failed; {} told by their state at the load, the "
      "others by their failure load{}){}",
      e.probability, e.low, e.high, e.cov, e.samples, e.failures, failure.judged_by_state(),
      e.unresolved ? fmt::format(", {} unresolved: {}", e.unresolved, first_why) : "",
      e.reached ? "" : fmt::format("; the coefficient of variation {:.3g} was not reached in {} samples", st.sampling_cov,
                                   st.max_samples)));
  if (e.failures > 0 && (form.probability < e.low || form.probability > e.high))
    out.summary.push_back("reliability: FORM's probability lies outside the Monte Carlo interval: W_fail bends between "
                          "the mean inputs and the design point; trust the Monte Carlo estimate");
  return true;
}

// The loads at the failure probabilities asked for, by inverse FORM.
void loads_at_probabilities(const FailureLoadFunction& h, const std::vector<UncertainInput>& inputs, double speed,
                            const ReliabilitySettings& st, const ProgressReport& progress, StudyOutcome& out) {
  const std::size_t n = inputs.size();
  for (const double p : st.probabilities) {
    if (progress) progress(fmt::format("reliability: the load at P_f = {:.3g}", p));
    const DesignPoint inverse = inverse_design_point(h, n, p);
    if (!inverse.converged) {
      out.summary.push_back(fmt::format("reliability: no load found at P_f = {:.3g}: {}", p, inverse.why));
      continue;
    }
    ReliabilityRow& r = out.own_part<ReliabilityOutcome>().rows.emplace_back();
    r.method = "inverse_form";
    r.load = inverse.load;
    r.speed = speed;
    r.probability = p;
    r.beta = inverse.beta;
    r.evaluations = inverse.evaluations;
    r.converged = true;
    add_design_point(out, "inverse_form", inverse, inputs);
    out.summary.push_back(fmt::format("reliability: the load at P_f = {:.3g} is {:.6g} N (inverse FORM, β = {:.3f}); "
                                      "design point: {}",
                                      p, inverse.load, inverse.beta, design_point_words(inverse, inputs)));
  }
}

}  // namespace

void run_reliability(BearingModel& model, StudyOutcome& out, const ProgressReport& progress, int threads,
                     SearchScheduler* scheduler) {
  // First: reliability.csv and design_point.csv are written (empty) where the study ends early.
  ReliabilityOutcome& reliability = out.own_part<ReliabilityOutcome>();
  const Scene& scene = model.scene();
  const ReliabilitySettings& st = std::get<ReliabilitySettings>(scene.study.settings);
  const std::vector<UncertainInput>& inputs = st.uncertain_inputs;
  const std::size_t n = inputs.size();
  std::vector<std::string> paths;
  std::vector<double> scales;
  for (const UncertainInput& in : inputs) {
    paths.push_back(in.path);
    scales.push_back(input_slope(in, 0.0));
  }
  FailureLoadAtInputs failure(scene, paths, scales, range_settings(st.search), threads);

  // The failure search at the inputs' medians (u = 0, where FORM starts): where every
  // move starts from.
  std::vector<double> medians(n);
  for (std::size_t i = 0; i < n; ++i) medians[i] = input_at(inputs[i], 0.0);
  std::string why;
  const DistressSearch* searched = failure.search_at(medians, progress, why);
  if (!searched) {
    out.solver_failed = true;
    out.message = "the scene refuses the inputs' medians: " + why;
    return;
  }
  const DistressSearch& found = *searched;
  add_search_work(out.timings, found.counts);
  out.distress.push_back(found.row);
  const double load = model.load(), speed = model.speed();
  if (!found.row.failure_load) {
    out.summary.push_back(fmt::format("reliability: the inputs' medians do not fail up to {:.6g} N ({}): no failure "
                                      "load to take the probability of; widen load_end",
                                      st.search.loads.end, found.row.method));
    return;
  }

  // W_fail at the inputs x(u), and its gradient in u.
  std::atomic<long> evaluations{0};
  const auto inputs_at = [&](std::span<const double> u) { return inputs_at_coordinates(inputs, u); };
  const FailureLoadFunction h = [&](std::span<const double> u, bool gradient,
                                    std::string& why) -> std::optional<FailureLoadValue> {
    ++evaluations;
    const std::optional<FailureAtInputs> f = failure.at(inputs_at(u), gradient, why);
    if (!f) return std::nullopt;
    FailureLoadValue v{f->load, {}};
    for (std::size_t i = 0; i < f->gradient.size(); ++i) v.gradient.push_back(f->gradient[i] * input_slope(inputs[i], u[i]));
    return v;
  };

  // FORM at the operating load.
  if (progress) progress(fmt::format("reliability: FORM at {:.6g} N", load));
  failure.keep_every_point(true);
  const DesignPoint form = design_point(h, n, load);
  // A probability only from a design point found: an unconverged iterate's is no answer.
  if (!form.converged) {
    out.solver_failed = true;
    out.message = "FORM did not find the design point: " + form.why;
    out.summary.push_back("reliability: " + out.message);
    return;
  }
  ReliabilityRow& row = reliability.rows.emplace_back();
  row.method = "form";
  row.load = load;
  row.speed = speed;
  row.converged = true;
  row.evaluations = form.evaluations;
  row.probability = form.probability;
  row.beta = form.beta;
  add_design_point(out, "form", form, inputs);
  out.summary.push_back(fmt::format("reliability at {:.6g} N, {}: P_f = {:.3g} by FORM (β = {:.3f}; W_fail "
                                    "{:.6g} N at the inputs' medians, {} failure loads evaluated)",
                                    load, speed_text(speed, scene.study.speeds_in_rpm), form.probability, form.beta, *found.row.failure_load, form.evaluations));
  out.summary.push_back("reliability: design point: " + design_point_words(form, inputs));
  failure.keep(inputs_at(form.u));

  // The Monte Carlo check round the design point: its samples start from the points
  // FORM settled, none from each other's.
  failure.keep_every_point(false);
  if (st.max_samples > 0 &&
      !importance_sampling_check(failure, form, inputs, load, speed, st, threads, scheduler, progress, out))
    return;

  failure.keep_every_point(true);
  loads_at_probabilities(h, inputs, speed, st, progress, out);
  if (failure.searches() > 1)
    out.summary.push_back(fmt::format("reliability: {} of the failure loads needed a failure search of their own (Newton "
                                      "could not follow one from a settled point)",
                                      failure.searches() - 1));
}

}  // namespace twb
