// The bearing's steady states on its cool branch at the operating load, and below it, at
// any inputs x (study type reliability, docs/physics.md section 17): what a Monte Carlo
// sample needs to tell whether the bearing fails at that load, without its failure load.
//
// A state at x is moved from the nearest state held, at that state's load, x walked
// towards in steps (halved where one fails). A step is taken where Newton reaches it in
// at most twelve undamped steps, the hottest film node's rise above the ambient changes by
// at most a factor of two, and the state is not shown unstable: the rise's bound keeps
// the move off the hot branch (whose rises at the same load are many times the cool
// one's: about 150 K against 10-45 K on the paper's washer at 115 N), the stability test
// off the unstable middle branch, which lies next to the cool one near the fold. Neither
// is a proof; both are checks a jump between branches would have to slip past.
// On the cool branch every criterion's margin falls with load (section 8), so a negative
// margin at a load at most the operating one proves the failure (W_fail below it), and
// positive margins at the operating load prove the bearing safe there (the branch reached
// it: no fold below). Where the cool branch ended below the load (W_d(x) < load) no move
// reaches x at the load: the caller then asks for the failure load itself.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/bearing_model.h"

namespace twb {

class RecordReader;
class RecordWriter;

class OperatingStates {
 public:
  // The bearing at inputs x (none, with why, where the scene refuses x).
  using BearingAt = std::function<std::unique_ptr<BearingModel>(std::span<const double> x, std::string& why)>;
  // `scales`: the inputs' typical moves (SI), by which the nearest held state is chosen.
  OperatingStates(double load, std::vector<double> scales, BearingAt bearing_at);

  struct State {
    std::vector<double> x, u;
    double load = 0.0;        // N, at most the operating load
    double rise = 0.0;        // the hottest film node above the ambient, K
    bool past_limit = false;  // a criterion's margin is negative here
  };
  double load() const { return load_; }
  // State u of `model` (inputs x, at its load).
  static std::shared_ptr<const State> state_of(const BearingModel& model, std::span<const double> x,
                                               std::vector<double> u);

  // Holds the state at the operating load at inputs x, moved from u, a state of x's cool
  // branch at `from_load` (a failure search's); false, with why, where it cannot be.
  bool hold_from_branch(std::span<const double> x, double from_load, std::span<const double> u, std::string& why);
  // Walks at the operating load from the nearest state held there towards x as far as
  // the branch goes, holding every state on the way (the way to FORM's design point,
  // round which the samples lie).
  void hold_towards(std::span<const double> x);

  // Whether the bearing at x fails at the operating load, and its state; none where that
  // is not shown (nothing held near, the branch ends, x refused). `at_load`: from states
  // at the operating load (a sample on FORM's safe side); else from states below it (one
  // on its failing side, whose cool branch most often ends below the operating load),
  // walked up in load at x until a margin is negative or the operating load is reached.
  // Safe from several threads at once; depends only on the states held.
  struct Verdict {
    bool fails = false;
    std::shared_ptr<const State> state;
  };
  std::optional<Verdict> judge(std::span<const double> x, bool at_load) const;

  // Monte Carlo samples' states are held between batches, in sample order, so that no
  // verdict depends on which thread judged what first.
  void hold_later(std::uint64_t sample, std::shared_ptr<const State> s);
  void hold_those_waiting();
  // The states waiting to be held (only sample `only`'s, if given) written for another
  // process of the study (MPI ranks share each batch's states, so that every rank holds
  // the same: reliability.cpp); and such states read, added to the states waiting or, with
  // `instead`, in their place. std::runtime_error for damaged bytes.
  void write_waiting(RecordWriter& out, std::optional<std::uint64_t> only = std::nullopt) const;
  void take_waiting(RecordReader& in, bool instead);
  std::size_t held() const;

 private:
  std::shared_ptr<const State> nearest(std::span<const double> x, bool at_load) const;
  // The states of the walk from `from` to x at from's load, the last at x where it got
  // there; steps shorter than `least` are not tried.
  std::vector<std::shared_ptr<const State>> walk(const State& from, std::span<const double> x, bool all,
                                                 double least, std::unique_ptr<BearingModel>* bearing = nullptr) const;
  // From `from` (a state of `model`, below the operating load) up the branch in load until
  // a criterion's margin is negative, else to the operating load: that state; none where
  // the branch cannot be followed.
  std::shared_ptr<const State> past_limit_up_to_load(BearingModel& model, const State& from) const;
  // The state of `model` Newton reaches from `from` in a move that stays on its branch;
  // none where it does not.
  std::shared_ptr<const State> settle_near(BearingModel& model, std::span<const double> x, const State& from) const;

  double load_;
  std::vector<double> scales_;
  BearingAt bearing_at_;
  mutable std::mutex lock_;
  std::vector<std::shared_ptr<const State>> held_;
  std::map<std::uint64_t, std::shared_ptr<const State>> waiting_;
};

}  // namespace twb
