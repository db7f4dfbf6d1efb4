// The whole `wattswath plan` command on small hole-free fields (issue 22: within 2x of the fastest
// peer, process start and file writing included): the executable run as a user runs it
// (fork + exec, `--no-report --json`, stdout to /dev/null, the four mission files written into a
// temporary folder) on the 2 ha rectangle and the L of bench/data at 10 m between lines, and on the
// 1 km^2 field at 30 m (the large-field lead must hold). Wall time per command; the counter
// `cpu_ms` is the command's own CPU time (user + system of the child, both threads).
// Baselines in the same run: `wattswath --version` (process start alone: the shared libraries
// loaded), the sharp-corner plan, and, when WATTSWATH_BASELINE_EXE names another build of the
// executable (e.g. one of an earlier commit), every command again with that one ("_baseline").
#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

const std::string kSource = WATTSWATH_SOURCE_DIR;

// Runs `argv` to completion with stdout and stderr on /dev/null; returns its CPU time [s]. Throws
// when it cannot start or does not exit with 0.
double runCommand(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    execv(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  rusage ru{};
  if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(argv[0] + " " + argv[1] + " failed (exit status " + std::to_string(status) + ")");
  return static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) + 1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

// Times `args` (after the executable) run by `exe`, `cpu_ms` as a counter.
void timeCommand(benchmark::State& state, const std::string& exe, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {exe};
  argv.insert(argv.end(), args.begin(), args.end());
  double cpu = 0.0;
  try {
    for (auto _ : state) cpu += runCommand(argv);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["cpu_ms"] = benchmark::Counter(1e3 * cpu / static_cast<double>(state.iterations()));
}

// `plan FIELD --spacing S --no-report --json` into a fresh temporary folder, plus `extra`.
std::vector<std::string> planArgs(const std::string& field, double spacing, const std::string& out,
                                  const std::vector<std::string>& extra) {
  std::vector<std::string> a = {"plan", kSource + "/bench/data/" + field, "--vehicle", kSource + "/data/vehicles/iris.json",
                                "--spacing", std::to_string(spacing), "--out", out, "--force", "--no-report", "--json"};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

// Registers every command for each executable of `exes` (name suffix, path) in turn, so that a
// baseline executable runs right after the one measured, under the same load.
void registerAll(const std::vector<std::pair<std::string, std::string>>& exes, const std::string& out) {
  struct Case {
    std::string name, field;
    double spacing;
    std::vector<std::string> extra;
  };
  const std::vector<Case> cases = {
      {"Rect2ha", "rect_2ha.geojson", 10.0, {}},
      {"Rect2ha_Sharp", "rect_2ha.geojson", 10.0, {"--corner-strategy", "sharp"}},
      {"LShape", "lshape.geojson", 10.0, {}},
      {"LShape_Sharp", "lshape.geojson", 10.0, {"--corner-strategy", "sharp"}},
      {"Field1km2", "field_1km2.geojson", 30.0, {}},
  };
  for (const auto& [suffix, exe] : exes)
    benchmark::RegisterBenchmark(("BM_ProcessStart" + suffix).c_str(),
                                 [exe = exe](benchmark::State& s) { timeCommand(s, exe, {"--version"}); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  for (const auto& c : cases)
    for (const auto& [suffix, exe] : exes) {
      const auto args = planArgs(c.field, c.spacing, out + "/" + c.name + suffix, c.extra);
      benchmark::RegisterBenchmark(("BM_PlanCommand_" + c.name + suffix).c_str(),
                                   [exe = exe, args](benchmark::State& s) { timeCommand(s, exe, args); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
}

}  // namespace

int main(int argc, char** argv) {
  char tmpl[] = "/tmp/bench_plan_command.XXXXXX";
  const char* out = mkdtemp(tmpl);
  if (!out) return 1;
  std::vector<std::pair<std::string, std::string>> exes = {{"", WATTSWATH_EXE}};
  if (const char* base = std::getenv("WATTSWATH_BASELINE_EXE"); base && *base) exes.emplace_back("_baseline", base);
  registerAll(exes, out);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::error_code ec;
  std::filesystem::remove_all(out, ec);
  return 0;
}
