#pragma once
// Shared helpers for the tests: where the sources, the reference data and the CLI are.
#include <cstdio>
#include <sys/wait.h>
#include <string>

namespace wattswath::test {

/// Path of a file in the source tree.
inline std::string sourcePath(const std::string& rel) { return std::string(WATTSWATH_SOURCE_DIR) + "/" + rel; }
/// Path of a file in ../shared/data.
inline std::string sharedData(const std::string& rel) { return std::string(WATTSWATH_SHARED_DATA_DIR) + "/" + rel; }
/// Path of the built CLI.
inline std::string cliBinary() { return WATTSWATH_BINARY; }

/// Result of running a shell command: exit status and captured stdout.
struct RunResult {
  int status = -1;     ///< exit status (WEXITSTATUS), or -1 when killed by a signal
  std::string output;  ///< stdout (and stderr when merged by the caller with 2>&1)
};

/// Runs `cmd` with /bin/sh and captures its stdout.
inline RunResult run(const std::string& cmd) {
  RunResult r;
  FILE* f = popen(cmd.c_str(), "r");
  if (!f) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, f)) > 0) r.output.append(buf, n);
  const int st = pclose(f);
  if (WIFEXITED(st)) r.status = WEXITSTATUS(st);
  return r;
}

}  // namespace wattswath::test
