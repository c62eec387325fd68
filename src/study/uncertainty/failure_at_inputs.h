// The failure load at any inputs (study type reliability, docs/physics.md section 17):
// W_fail(x), the least load of the criteria a failure search located at one x, each
// followed to another by Newton from the nearest point already settled (the fold on the
// minimally augmented system from its predicted move, a limit's crossing on its
// margin's root), on the bearing built from the scene read again with x. Where Newton
// cannot reach x in one move, the move is walked in shorter steps (down to a quarter);
// where it still cannot, or where a criterion not followed is crossed below the followed
// one at x, the failure search runs again at x. ∇W_fail by
// the left null vector (the fold) or the margin's slopes (a crossing), as the
// sensitivity study takes them.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "model/bearing_model.h"
#include "solver/fold_location.h"
#include "study/searches/distress_search.h"
#include "study/searches/operating_states.h"
#include "twb/scene/scene.h"

namespace twb {

// The failure load at x: `load` (+∞ where nothing fails up to the search's load_end),
// the criterion setting it (distress.csv's words), and with a gradient dW_fail/dx_i in
// the inputs' SI units.
struct FailureAtInputs {
  double load = 0.0;
  std::string criterion;
  std::vector<double> gradient;
  bool searched = false;  // found by a failure search at x, not by Newton from a settled point
};

class FailureLoadAtInputs {
 public:
  // `paths`: the inputs x stands for, in order; `scales` their typical moves (SI), by
  // which the nearest settled point is chosen. The scene's study is left out. A gradient
  // is taken over `threads` threads.
  FailureLoadAtInputs(const Scene& scene, std::vector<std::string> paths, std::vector<double> scales,
                      DistressSearchSettings search, int threads);
  ~FailureLoadAtInputs();

  // The failure search at inputs x (e.g. the inputs' medians), whose criteria every
  // later move starts from; none, with why, where the scene refuses x.
  const DistressSearch* search_at(std::span<const double> x, const SearchProgress& progress, std::string& why);

  // W_fail at x; none, with why, where x is outside an input's range or no state can be
  // settled there. Safe to call from several threads at once.
  std::optional<FailureAtInputs> at(std::span<const double> x, bool gradient, std::string& why) const;

  // Whether the bearing at x fails at `load` (W_fail(x) ≤ load), a Monte Carlo sample's
  // question: followed from the nearest settled point as at() does, else by a failure
  // search that ends just above `load` instead of at the study's load_end (whether the
  // bearing fails there needs no more of the branch) and settles nothing. None, with why,
  // as for at(). Safe to call from several threads at once.
  // A Monte Carlo sample: its number, and whether it lies on FORM's safe side (its state
  // at the load, where operate_at holds states, is moved from the states held at the load
  // there; on the failing side, where it most often does not exist, only from states below
  // the load). A sample's state at the load, where
  // it has one, is held for later samples once hold_samples() is called (between
  // batches: see OperatingStates).
  struct Sample {
    std::uint64_t number = 0;
    bool likely_safe = true;
  };
  std::optional<bool> fails_at(std::span<const double> x, double load, std::string& why,
                               std::optional<Sample> sample = std::nullopt) const;
  // Prepares fails_at at `load`: the first search's cool branch moved to that load, and
  // walked towards the inputs `towards` (the design point round which the samples lie).
  // Where the first search's branch does not reach the load (it ends below it, or Newton
  // cannot move it there), every sample is told by its failure load.
  void operate_at(double load, std::span<const double> towards);
  void hold_samples();
  // Samples judged by their state at the load (operate_at), not by a failure load.
  long judged_by_state() const { return judged_by_state_; }
  // The states held that samples start from (operate_at's and the samples' own).
  std::size_t states_held() const { return operating_ ? operating_->held() : 0; }
  // Samples judged by other processes of the study (MPI ranks: reliability.cpp). What this
  // process learnt judging `sample` (fails_at, just before): how it was told and the state
  // it leaves to hold, written; and such a report read here, as if it had been judged here.
  void write_sample_report(RecordWriter& out, std::uint64_t sample) const;
  void take_sample_report(RecordReader& in, std::uint64_t sample);
  // The states a batch's samples leave to hold, for the processes that judged only some
  // of them; taken there in place of their own, so that every process holds the same.
  void write_batch_states(RecordWriter& out) const;
  void take_batch_states(RecordReader& in);

  // Settle at x and keep it as a point later moves start from (e.g. the design point).
  void keep(std::span<const double> x);
  // Whether every point settled is kept too (each later move then starts nearer): for a
  // sequence of evaluations on one thread (FORM), not for samples spread over threads,
  // whose results must not depend on which thread settled what first.
  void keep_every_point(bool keep) { keeping_ = keep; }

  long searches() const { return searches_; }  // failure searches run (search_at's included)

  struct Settled;  // a bearing at some x with its criteria settled
  // A point of a followed map (study/followed_map.cpp): W_fail there, the fold and the
  // crossings settled, and what the next move starts from.
  struct Followed {
    std::shared_ptr<const Settled> point;
    FailureAtInputs failure;                               // load +∞ where nothing fails
    std::optional<double> fold;                            // W_d, where a fold is settled
    std::vector<std::pair<LimitKind, double>> crossings;   // each settled criterion's load
    std::optional<DistressRow> search_row;                 // where a failure search ran at x
  };
  // W_fail at x followed from a point settled before (Newton along the move, walked in
  // shorter steps where one fails), else, or without `from`, by a failure search at x.
  // Depends only on `from` and x, not on what else was settled: safe from several
  // threads, whose results do not depend on their order. None, with why, where the scene
  // refuses x.
  std::optional<Followed> follow(const Followed* from, std::span<const double> x, std::string& why) const;

 private:
  // Whether a criterion not followed is crossed in the state where W_fail is set (a lower
  // failure load, which a search must find).
  bool crosses_unfollowed(const Settled& s) const;
  std::unique_ptr<Settled> settle_once(const Settled& from, std::span<const double> x, std::string& why) const;
  std::unique_ptr<Settled> walk(const Settled& from, std::span<const double> x, std::string& why) const;
  void remember(std::unique_ptr<Settled> s) const;
  std::unique_ptr<Settled> searched_at(std::span<const double> x, std::string& why) const;
  std::unique_ptr<Settled> settled_at(std::span<const double> x, std::string& why) const;
  // W_fail at x moved from the nearest settled point; none where there is none, Newton
  // cannot make the move or a criterion not followed comes first (`refused` set, with
  // why, where the scene refuses x itself).
  std::unique_ptr<Settled> from_nearest(std::span<const double> x, std::string& why, bool& refused) const;
  std::unique_ptr<BearingModel> model_at(std::span<const double> x, std::string& why) const;
  // A sample's state u of `model` (inputs x) at `load`, held for the next batches' samples.
  void hold_later(const Sample& sample, BearingModel& model, std::span<const double> x, double load,
                  const std::vector<double>& u) const;
  // A Settled at x with its bearing built and nothing settled on it yet; none, with why,
  // where the scene refuses x.
  std::unique_ptr<Settled> bearing_at(std::span<const double> x, std::string& why) const;

  Scene scene_;
  std::vector<std::string> paths_;
  std::vector<double> scales_;
  DistressSearchSettings search_;
  int threads_ = 1;
  DistressSearch first_search_;
  std::vector<double> first_x_;  // its inputs
  // The points moves start from: the first search's, and while keeping, every point
  // settled on the way.
  mutable std::vector<std::shared_ptr<const Settled>> anchors_;
  mutable std::mutex anchors_lock_;
  bool keeping_ = false;
  // Of a move: the shortest step tried (1, ½, ¼) before Newton is given up for a failure
  // search at the target, which costs about as much as three failed steps (past a cusp).
  static constexpr double kLeastStep = 0.25;
  mutable std::atomic<long> searches_{0};
  std::unique_ptr<OperatingStates> operating_;
  mutable std::atomic<long> judged_by_state_{0};
  // How each sample of the batch was told, for its report.
  enum class Told : std::uint8_t { by_failure_load, by_state, by_search };
  void note(const std::optional<Sample>& sample, Told how) const;
  mutable std::mutex told_lock_;
  mutable std::map<std::uint64_t, Told> told_;
};

}  // namespace twb
