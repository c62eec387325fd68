// SIGINT and SIGTERM end a run cleanly: a message saying what is left, and the exit
// status of the signal (128 + its number). Results are written only once the study is
// done, run.json last, and each file atomically (results/atomic_file.h); the results
// directory was emptied of earlier runs when the run began (results_directory.h), so
// an interrupted run leaves no file of its own, or a set without run.json: never a
// half-written file, never a mix with an earlier run.
#pragma once

namespace twb::cli {

// Installs the handlers; `directory` must outlive the run (it is named in the message).
void end_cleanly_on_interruption(const char* directory);
// Once run.json is written the run is complete: a signal then ends it as usual.
void run_is_complete();

}  // namespace twb::cli
