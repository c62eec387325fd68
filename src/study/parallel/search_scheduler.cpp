#include "study/parallel/search_scheduler.h"

#include <stdexcept>

#include <fmt/format.h>

#include "study/parallel/parallel.h"

namespace twb {

void ThreadScheduler::run(const std::vector<std::size_t>& todo, int threads, const Work& work) {
  run_in_parallel(todo.size(), threads, [&](std::size_t k) { work.run_here(todo[k]); });
}

SliceScheduler::SliceScheduler(int slice, int slices) : slice_(slice), slices_(slices) {
  if (slices < 1 || slice < 1 || slice > slices)
    throw std::invalid_argument(fmt::format("slice {}/{}: K must be in 1..N", slice, slices));
}

std::vector<std::size_t> SliceScheduler::searches(std::size_t total) const {
  std::vector<std::size_t> mine;
  for (std::size_t i = std::size_t(slice_ - 1); i < total; i += std::size_t(slices_)) mine.push_back(i);
  return mine;
}

void SliceScheduler::run(const std::vector<std::size_t>& todo, int threads, const Work& work) {
  std::vector<std::size_t> mine;
  for (std::size_t i : todo)
    if (i % std::size_t(slices_) == std::size_t(slice_ - 1)) mine.push_back(i);
  run_in_parallel(mine.size(), threads, [&](std::size_t k) { work.run_here(mine[k]); });
}

void JournalOnlyScheduler::run(const std::vector<std::size_t>& todo, int, const Work&) {
  if (todo.empty()) return;
  std::string list;
  for (std::size_t k = 0; k < todo.size() && k < 20; ++k) list += fmt::format("{}{}", k ? ", " : "", todo[k] + 1);
  if (todo.size() > 20) list += ", ...";
  throw std::invalid_argument(fmt::format(
      "{} of the study's searches are in none of the slices' journals (searches {}, counted from 1): run the "
      "slices that hold them (twb run --slice K/N), or --resume a slice that was stopped",
      todo.size(), list));
}

}  // namespace twb
