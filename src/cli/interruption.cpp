#include "interruption.h"

#include <csignal>
#include <cstring>

#include <unistd.h>

namespace twb::cli {

namespace {

// A copy: the handler may run after the caller's string is gone.
char results_directory[4096] = {};

void write_text(const char* text) {
  if (::write(STDERR_FILENO, text, std::strlen(text)) < 0) return;
}

// Only async-signal-safe calls: write(2) and _exit(2).
extern "C" void on_interruption(int signal) {
  write_text(signal == SIGINT ? "\ntwb: interrupted (SIGINT)" : "\ntwb: terminated (SIGTERM)");
  write_text("; no complete run was written to ");
  write_text(results_directory[0] ? results_directory : "the results directory");
  write_text(" (a complete run ends with run.json); run it again, with --resume to keep the searches a sweep or "
             "map finished\n");
  ::_exit(128 + signal);
}

}  // namespace

void end_cleanly_on_interruption(const char* directory) {
  std::strncpy(results_directory, directory, sizeof results_directory - 1);
  struct sigaction action {};
  action.sa_handler = on_interruption;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

void run_is_complete() {
  ::signal(SIGINT, SIG_DFL);
  ::signal(SIGTERM, SIG_DFL);
}

}  // namespace twb::cli
