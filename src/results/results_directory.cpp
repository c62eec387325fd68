#include "twb/results/results_directory.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <regex>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "twb/error_family.h"

namespace twb {

namespace {

namespace fs = std::filesystem;

// Every file a run or the plotting script writes, by name: anything else a user keeps
// in the directory stays.
void remove_earlier_run(const fs::path& dir) {
  for (const char* name : {"run.json", "states.csv", "distress.csv", "sliding.csv", "fold_curve.csv", "trajectory.csv",
                           "sensitivity.csv", "reliability.csv", "design_point.csv", "calibration.csv",
                           "calibration_correlation.csv", "calibration_points.csv", "cycle_events.csv",
                           "cycle_end_state.json", "life.csv", "worn_profile.csv", "worn_washer.json"})
    fs::remove(dir / name);
  static const std::regex field_file(R"(state_[0-9]{4,}\.csv)");
  static const std::regex figure_file(R"(.+\.(png|svg|pdf))");
  const std::pair<const char*, const std::regex*> owned[] = {{"fields", &field_file}, {"figures", &figure_file}};
  for (const auto& [sub, pattern] : owned) {
    if (!fs::is_directory(dir / sub)) continue;
    for (const fs::directory_entry& e : fs::directory_iterator(dir / sub))
      if (e.is_regular_file() && std::regex_match(e.path().filename().string(), *pattern)) fs::remove(e.path());
  }
}

}  // namespace

ResultsDirectory::ResultsDirectory(const fs::path& dir) : dir_(dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw IoError("cannot make the results directory", dir.string(), ec ? ec.value() : ENOTDIR);
  const fs::path lock = dir / ".twb.lock";
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) throw IoError("cannot write into the results directory", dir.string(), errno);
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    char pid[32] = {};
    const ssize_t n = ::pread(lock_fd_, pid, sizeof pid - 1, 0);
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw ResultsDirectoryError(fmt::format(
        "another twb run{} is writing into '{}'; wait for it to finish or give this run another --out",
        n > 0 ? fmt::format(" (process {})", std::string(pid, std::size_t(n))) : "", dir.string()));
  }
  // A constructor that throws runs no destructor: the lock is released here.
  auto give_up = [&](const char* failed, int error) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw IoError(failed, dir.string(), error);
  };
  const std::string me = std::to_string(::getpid());
  // A short write sets no errno: it is a full disk.
  if (::ftruncate(lock_fd_, 0) != 0) give_up("cannot write into the results directory", errno);
  const ssize_t written = ::pwrite(lock_fd_, me.data(), me.size(), 0);
  if (written != ssize_t(me.size())) give_up("cannot write into the results directory", written < 0 ? errno : ENOSPC);
  try {
    remove_earlier_run(dir);
  } catch (const fs::filesystem_error& e) {
    give_up("cannot clear an earlier run's files from", e.code().value());
  }
}

ResultsDirectory::~ResultsDirectory() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the flock
}

}  // namespace twb
