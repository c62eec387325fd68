// The threads of a study's pool that no search is waiting for. A study runs its
// independent searches one per thread (study_searches.cpp); once fewer searches are left
// than threads, the idle ones may serve a running search's own independent pieces (the
// check of its start's branch, on a model of its own, and its error bars, each on its own
// refined model), so that a study of one speed on two cores does not leave one idle.
// The pieces only read the search's model (its scene, interpolation from it), never
// evaluate it. Lending changes where a piece runs, never what it computes.
#pragma once

#include <algorithm>
#include <cstddef>
#include <mutex>

namespace twb {

class SpareThreads {
 public:
  SpareThreads(int threads, std::size_t searches) : free_(long(std::max(threads, 1)) - long(searches)) {}
  // Up to `wanted` threads for the caller's pieces (none while every thread has a search).
  int borrow(int wanted) {
    const std::lock_guard<std::mutex> hold(lock_);
    const long lent = std::clamp<long>(free_, 0, std::max(wanted, 0));
    free_ -= lent;
    return int(lent);
  }
  void give_back(int threads) {
    const std::lock_guard<std::mutex> hold(lock_);
    free_ += threads;
  }
  // A search is done: the thread that ran it has one search fewer to wait for.
  void search_finished() { give_back(1); }

 private:
  std::mutex lock_;
  long free_;  // threads less the searches not yet finished and the threads lent
};

// Threads borrowed for as long as the holder lives.
class BorrowedThreads {
 public:
  BorrowedThreads(SpareThreads* spare, int wanted) : spare_(spare), count_(spare ? spare->borrow(wanted) : 0) {}
  ~BorrowedThreads() {
    if (spare_) spare_->give_back(count_);
  }
  BorrowedThreads(const BorrowedThreads&) = delete;
  BorrowedThreads& operator=(const BorrowedThreads&) = delete;
  int count() const { return count_; }

 private:
  SpareThreads* spare_;
  int count_;
};

}  // namespace twb
