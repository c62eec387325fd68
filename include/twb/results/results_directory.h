// The results directory of a run, made safe before any work is done: created and
// proven writable, locked against a second run writing into it at the same time (an
// flock, which the kernel releases when the run dies, so a killed run leaves no stale
// lock), and emptied of an earlier run's files, so that no table or figure mixes two
// runs. run.json is written last: a directory without it holds no complete run.
// twb run and twb.run(out=DIR) claim it before they build the model, then run into it
// (Bearing::run_into).
#pragma once

#include <filesystem>
#include <stdexcept>

namespace twb {

// A directory another run is writing into: the user's to settle, so an invalid argument
// of the error family (exit status 2). A directory that cannot be made or written into
// is an IoError (twb/error_family.h), the system's.
struct ResultsDirectoryError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

class ResultsDirectory {
 public:
  explicit ResultsDirectory(const std::filesystem::path& dir);
  ~ResultsDirectory();
  const std::filesystem::path& path() const { return dir_; }
  ResultsDirectory(const ResultsDirectory&) = delete;
  ResultsDirectory& operator=(const ResultsDirectory&) = delete;

 private:
  std::filesystem::path dir_;
  int lock_fd_ = -1;
};

}  // namespace twb
