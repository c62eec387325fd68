// A duty cycle's watch on the failure criteria (docs/physics.md section 19): every
// sample of the trajectory with the least allowance it leaves, each crossing of a
// criterion's limit and each recovery located in time, the cycle's events, and its
// worst moment.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/bearing_model.h"
#include "model/failure_margins.h"
#include "twb/study/study_outcome.h"

namespace twb {

class CycleWatch {
 public:
  // Where between two of the march's steps (times a < b) a criterion's margin is zero:
  // the inputs there (their time the crossing's), none where it cannot say.
  using CrossingLocator = std::function<std::optional<SchedulePoint>(double a, double b, LimitKind kind)>;

  // `lowest_ambient`: the schedule's, from which every allowance is measured (the reader
  // keeps the first point's ambient below every limit; a later, warmer ambient must not
  // shrink an allowance to nothing just as the limit is crossed).
  CycleWatch(const BearingModel& model, StudyOutcome& out, double lowest_ambient, CrossingLocator locate)
      : limits_(OperatingLimits::of(model.scene())), thermal_(model.scene().effects.thermal), out_(out),
        events_(out.own_part<DutyCycleOutcome>().events), allowances_(allowances(limits_, lowest_ambient)),
        locate_(std::move(locate)) {}

  // The sample at t (the model's inputs already those of t), its crossings since the
  // sample before.
  void sample(double t, const SchedulePoint& inputs, BearingState state);

  CycleEvent& event(std::string what, double t, const SchedulePoint& inputs);

  std::optional<std::size_t> worst() const { return worst_; }
  // The scene's limits, each criterion's margin measured from them.
  const OperatingLimits& limits() const { return limits_; }

 private:
  // How far each criterion lets a state move from rest, from the lowest ambient (none
  // where the scene applies none): what a sample's least margin is a share of.
  static PerCriterion<std::optional<double>> allowances(const OperatingLimits& limits, double ambient);

  OperatingLimits limits_;
  bool thermal_;
  StudyOutcome& out_;                // the trajectory's samples
  std::vector<CycleEvent>& events_;  // out_'s DutyCycleOutcome's
  PerCriterion<std::optional<double>> allowances_;
  std::optional<FailureMargins> last_margins_;
  std::optional<std::size_t> worst_;
  CrossingLocator locate_;
};

}  // namespace twb
