// Where a study's independent distress searches run (one per speed and parameter value
// or sliding film; study_runner.cpp's run_searches): on this process's threads (the
// default), on the ranks of an MPI job (src/cli/mpi_searches.cpp), or one fixed slice of
// them for a job array (twb run --slice K/N, combined by twb merge). Whatever runs where,
// the process that writes the study's files takes every search in the study's order, so
// the files are the same, byte for byte, as a run on one thread.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace twb {

class SearchScheduler {
 public:
  struct Work {
    // Runs search i on the calling thread and takes its result in this process.
    std::function<void(std::size_t)> run_here;
    // Runs search i for another process: its result as a journal entry (search_journal.h).
    std::function<std::string(std::size_t)> run_for_another;
    // Takes search i's result, run by another process, from its journal entry.
    std::function<void(std::size_t, const std::string&)> arrived;
  };
  virtual ~SearchScheduler() = default;
  // `todo`: the searches the journal does not hold yet, in the study's order; `threads`:
  // this process's threads for them.
  virtual void run(const std::vector<std::size_t>& todo, int threads, const Work& work) = 0;
  // Whether this process takes the study's results (and writes its files).
  virtual bool takes_results() const { return true; }
  // What the process that takes the results holds (`bytes` there) given to every other
  // process of the study (`bytes` replaced there): for searches that start from what
  // earlier ones found (a reliability study's Monte Carlo batches). Every process calls
  // it at the same point of the study; one process alone has nothing to share.
  virtual void share(std::string& bytes) { (void)bytes; }
};

// Every search here, on `threads` threads.
class ThreadScheduler final : public SearchScheduler {
 public:
  void run(const std::vector<std::size_t>& todo, int threads, const Work& work) override;
};

// Slice `slice` (1-based) of `slices`: the searches i with i mod slices = slice − 1, here
// on `threads` threads, each journaled as it finishes; the study's files are made by
// twb merge from all slices' journals. Every slice of a study gets as many searches
// as any other, give or take one, and neighbouring speeds go to different slices, so
// that searches of similar cost are spread evenly.
class SliceScheduler final : public SearchScheduler {
 public:
  SliceScheduler(int slice, int slices);
  void run(const std::vector<std::size_t>& todo, int threads, const Work& work) override;
  bool takes_results() const override { return false; }
  // The searches of a study of `total` that belong to this slice.
  std::vector<std::size_t> searches(std::size_t total) const;

 private:
  int slice_, slices_;
};

// twb merge: every search must come from the slices' journals; one that did not is an
// error naming it (std::invalid_argument), rather than a search run here unasked.
class JournalOnlyScheduler final : public SearchScheduler {
 public:
  void run(const std::vector<std::size_t>& todo, int threads, const Work& work) override;
};

}  // namespace twb
