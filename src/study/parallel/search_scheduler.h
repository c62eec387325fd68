// The schedulers twb itself has (the interface: twb/study/search_scheduler.h): this
// process's threads, a slice of a job array, and the slices' journals alone (twb merge).
#pragma once

#include <cstddef>
#include <vector>

#include "twb/study/search_scheduler.h"

namespace twb {

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
