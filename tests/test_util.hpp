#pragma once
// Shared helpers for the tests: where the sources, the reference data and the CLI are.
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>
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

/// The bytes of a file (empty when it cannot be read).
inline std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// FNV-1a 64 of a file's bytes, and its size: "unchanged" means both are equal.
inline std::pair<std::uint64_t, std::uintmax_t> fingerprint(const std::string& path) {
  const std::string bytes = readAll(path);
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return {h, bytes.size()};
}

/// How a run of the CLI ended.
struct Outcome {
  bool signalled = false;  ///< killed by a signal (crash, abort, or the watchdog)
  int signal = 0;          ///< the signal when signalled
  int status = -1;         ///< exit status otherwise
  std::string out, err;    ///< captured stdout and stderr
};

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAsan = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAsan = true;
#else
inline constexpr bool kAsan = false;
#endif
#else
inline constexpr bool kAsan = false;
#endif

/// Runs the CLI without a shell (so a signal is seen as a signal, not as an exit status 128+n),
/// from the source folder, with a watchdog: SIGALRM after `seconds` turns a hang into a failure,
/// and (outside address-sanitizer builds) a 4 GB address-space limit turns a runaway allocation
/// into std::bad_alloc.
inline Outcome runCli(const std::vector<std::string>& args, unsigned seconds = 60) {
  namespace fs = std::filesystem;
  const fs::path tmp = fs::temp_directory_path() / ("wattswath_bad_" + std::to_string(::getpid()));
  fs::create_directories(tmp);
  const std::string out_path = (tmp / "stdout").string(), err_path = (tmp / "stderr").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int o = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (o < 0 || e < 0 || ::chdir(WATTSWATH_SOURCE_DIR) != 0) ::_exit(127);
    ::dup2(o, 1);
    ::dup2(e, 2);
    if (!kAsan) {
      rlimit lim{4ull << 30, 4ull << 30};
      ::setrlimit(RLIMIT_AS, &lim);
    }
    ::alarm(seconds);
    std::vector<char*> argv;
    const std::string bin = cliBinary();
    argv.push_back(const_cast<char*>(bin.c_str()));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(bin.c_str(), argv.data());
    ::_exit(127);
  }
  Outcome r;
  int st = 0;
  ::waitpid(pid, &st, 0);
  if (WIFSIGNALED(st)) {
    r.signalled = true;
    r.signal = WTERMSIG(st);
  } else if (WIFEXITED(st)) {
    r.status = WEXITSTATUS(st);
  }
  r.out = readAll(out_path);
  r.err = readAll(err_path);
  std::error_code ec;
  fs::remove_all(tmp, ec);
  return r;
}

}  // namespace wattswath::test
