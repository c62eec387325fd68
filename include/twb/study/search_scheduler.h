// Where a study's independent distress searches run (one per speed and parameter value
// or sliding film): on this process's threads (the default, RunOptions::scheduler
// unset), on the ranks of an MPI job (twb run under mpirun), one fixed slice of them for
// a job array (twb run --slice K/N), or wherever a program embedding twb sends them.
// Whatever runs where, the process that takes the study's results takes every search in
// the study's order, so its files are the same, byte for byte, as a run on one thread.
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
    // Runs search i for another process: its result as bytes to hand to that process's
    // `arrived` (the format of a results directory's journal entries).
    std::function<std::string(std::size_t)> run_for_another;
    // Takes search i's result, run by another process, from its bytes.
    std::function<void(std::size_t, const std::string&)> arrived;
  };
  virtual ~SearchScheduler() = default;
  // `todo`: the searches not journaled yet, in the study's order; `threads`: this
  // process's threads for them.
  virtual void run(const std::vector<std::size_t>& todo, int threads, const Work& work) = 0;
  // Whether this process takes the study's results (and writes its files).
  virtual bool takes_results() const { return true; }
  // What the process that takes the results holds (`bytes` there) given to every other
  // process of the study (`bytes` replaced there): for searches that start from what
  // earlier ones found (a reliability study's Monte Carlo batches). Every process calls
  // it at the same point of the study; one process alone has nothing to share.
  virtual void share(std::string& bytes) { (void)bytes; }
};

}  // namespace twb
