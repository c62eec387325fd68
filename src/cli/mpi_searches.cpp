#include "mpi_searches.h"

#include <cstdlib>

#ifdef TWB_WITH_MPI
// The C interface only: Open MPI's and MPICH's deprecated C++ bindings need a library of their own.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <optional>
#include <utility>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "results/record_bytes.h"
#include "twb/error_family.h"
#endif

namespace twb::cli {

#ifdef TWB_WITH_MPI

namespace {

// Started by a launcher: Open MPI's mpirun, or any PMI/PMIx one (MPICH, Slurm's srun).
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

constexpr int kAsk = 1;     // rank → 0: the search just run (if any) and a request for the next
constexpr int kAssign = 2;  // 0 → rank: the next search, or kNone

constexpr std::int64_t kNone = -1;

// A request: whether a search was run, and if so its number and its journal entry.
std::string ask(const std::optional<std::pair<std::size_t, std::string>>& result) {
  RecordWriter out;
  out(result.has_value());
  if (result) out(std::uint64_t(result->first)), out(result->second);
  return out.take();
}

// A failed call is the machine's or the network's, not a bug: an IoError with MPI's words.
void check(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING] = {};
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw IoError(std::string("MPI: ") + call + " failed: " + std::string(text, std::size_t(length)));
}

}  // namespace

MpiJob::MpiJob(int& argc, char**& argv) {
  if (!launched_by_mpi()) return;
  // Only the main thread calls MPI; rank 0's searches run on threads of their own.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  initialized_ = true;
  // A failed call returns its code, so that the error says which call and why; MPI's
  // default handler would end the job without a word from twb.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiJob::~MpiJob() {
  if (initialized_) MPI_Finalize();
}

void MpiJob::abort(int status) const {
  if (initialized_ && size_ > 1) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

void MpiScheduler::run(const std::vector<std::size_t>& todo, int threads, const Work& work) {
  if (job_.rank() != 0) {
    // A worker: ask, run what is assigned, send it back with the next request.
    std::optional<std::pair<std::size_t, std::string>> result;
    for (;;) {
      const std::string msg = ask(result);
      result.reset();
      check(MPI_Send(msg.data(), int(msg.size()), MPI_BYTE, 0, kAsk, MPI_COMM_WORLD), "MPI_Send");
      std::int64_t search = kNone;
      check(MPI_Recv(&search, 1, MPI_INT64_T, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
      if (search == kNone) return;
      result.emplace(std::size_t(search), work.run_for_another(std::size_t(search)));
    }
  }

  // Rank 0: one counter over `todo` for its own threads and for every other rank's requests.
  std::atomic<std::size_t> next{0};
  auto claim = [&]() -> std::optional<std::size_t> {
    const std::size_t k = next++;
    if (k < todo.size()) return todo[k];
    return std::nullopt;
  };
  std::vector<std::thread> own;
  // However this function is left (a damaged message throws), rank 0's own searches are
  // let finish and no new one begins, before the error ends the job (main: MPI_Abort).
  struct Finish {
    std::vector<std::thread>& threads;
    std::atomic<std::size_t>& next;
    std::size_t end;
    ~Finish() {
      next = end;
      for (std::thread& t : threads)
        if (t.joinable()) t.join();
    }
  } finish{own, next, todo.size()};
  for (int t = 0; t < std::max(threads, 1); ++t)
    own.emplace_back([&]() {
      while (const auto i = claim()) work.run_here(*i);
    });
  // Polled with a short sleep, so that waiting for requests does not take a core from the
  // searches (a blocking receive spins in Open MPI).
  int working = job_.size() - 1;
  std::string buffer;
  while (working > 0) {
    int flag = 0;
    MPI_Status status;
    check(MPI_Iprobe(MPI_ANY_SOURCE, kAsk, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe");
    if (!flag) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      continue;
    }
    int bytes = 0;
    check(MPI_Get_count(&status, MPI_BYTE, &bytes), "MPI_Get_count");
    buffer.resize(std::size_t(bytes));
    check(MPI_Recv(buffer.data(), bytes, MPI_BYTE, status.MPI_SOURCE, kAsk, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "MPI_Recv");
    RecordReader in(buffer, fmt::format("rank {}'s request", status.MPI_SOURCE));
    bool has_result = false;
    in(has_result);
    if (has_result) {
      std::uint64_t search = 0;
      std::string entry;
      in(search), in(entry);
      work.arrived(std::size_t(search), entry);
    }
    in.finish();
    const auto i = claim();
    const std::int64_t assign = i ? std::int64_t(*i) : kNone;
    check(MPI_Send(&assign, 1, MPI_INT64_T, status.MPI_SOURCE, kAssign, MPI_COMM_WORLD), "MPI_Send");
    if (!i) --working;
  }
}

void MpiScheduler::share(std::string& bytes) {
  std::int64_t size = std::int64_t(bytes.size());
  check(MPI_Bcast(&size, 1, MPI_INT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
  bytes.resize(std::size_t(size));
  // In pieces: a count is an int.
  constexpr std::int64_t kPiece = std::int64_t(1) << 30;
  for (std::int64_t at = 0; at < size; at += kPiece)
    check(MPI_Bcast(bytes.data() + at, int(std::min(kPiece, size - at)), MPI_BYTE, 0, MPI_COMM_WORLD), "MPI_Bcast");
}

bool built_with_mpi() { return true; }

#else

MpiJob::MpiJob(int&, char**&) {}
MpiJob::~MpiJob() = default;
void MpiJob::abort(int status) const { std::exit(status); }
void MpiScheduler::run(const std::vector<std::size_t>& todo, int threads, const Work& work) {
  ThreadScheduler().run(todo, threads, work);
}
void MpiScheduler::share(std::string&) {}
bool built_with_mpi() { return false; }

#endif

}  // namespace twb::cli
