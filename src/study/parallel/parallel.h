// The study's independent pieces on several threads: each piece runs whole on one thread
// with its own model and solvers (what they share they only read: a scene, a coarse
// model's state to interpolate from), so the results do not depend on the thread count;
// callers put them in order themselves.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "study/study_runner.h"

namespace twb {

// Calls piece(i) for every i in [0, count), on up to `threads` threads (the calling one
// among them), each i exactly once; returns when all are done. What a piece throws (an
// internal error, which no piece may turn into a result) is thrown again on the calling
// thread, the lowest i's first, whatever the thread count: an exception leaving a
// worker thread would end the process.
template <class Piece>
void run_in_parallel(std::size_t count, int threads, const Piece& piece) {
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> failed(count);
  auto work = [&]() {
    for (std::size_t i; (i = next++) < count;) {
      try {
        piece(i);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    }
  };
  const std::size_t workers = std::min<std::size_t>(std::max(threads, 1), std::max<std::size_t>(count, 1));
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

// The same report, one line at a time whatever thread calls it (empty stays empty).
inline ProgressReport one_line_at_a_time(const ProgressReport& progress, std::mutex& lock) {
  if (!progress) return {};
  return [&progress, &lock](const std::string& s) {
    const std::lock_guard<std::mutex> hold(lock);
    progress(s);
  };
}

}  // namespace twb
