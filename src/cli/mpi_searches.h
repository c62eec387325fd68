// A study's searches spread over the ranks of an MPI job (`mpirun -np N twb run SCENE`),
// for the twb command built with MPI (TWB_WITH_MPI). Rank 0 hands out the searches one at
// a time, in the study's order, to whichever rank asks first (dynamic balancing: a search
// past a fold costs ten times one without) and runs searches itself between answers;
// every other rank runs one search at a time and sends its result back as a journal
// entry. Rank 0 alone takes the results, journals them and writes the results directory,
// the same bytes as a run on one thread.
#pragma once

#include "study/parallel/search_scheduler.h"

namespace twb::cli {

class MpiJob {
 public:
  // MPI initialized when the command was started by mpirun (its environment says so);
  // otherwise a job of one rank without MPI.
  MpiJob(int& argc, char**& argv);
  ~MpiJob();
  MpiJob(const MpiJob&) = delete;
  MpiJob& operator=(const MpiJob&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool active() const { return size_ > 1; }
  // Ends every rank at once (an error on rank 0 would leave the others waiting for work).
  [[noreturn]] void abort(int status) const;

 private:
  bool initialized_ = false;
  int rank_ = 0, size_ = 1;
};

class MpiScheduler final : public SearchScheduler {
 public:
  explicit MpiScheduler(const MpiJob& job) : job_(job) {}
  void run(const std::vector<std::size_t>& todo, int threads, const Work& work) override;
  bool takes_results() const override { return job_.rank() == 0; }
  void share(std::string& bytes) override;

 private:
  const MpiJob& job_;
};

// Whether this build can run under MPI.
bool built_with_mpi();

}  // namespace twb::cli
