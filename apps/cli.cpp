#include "cli.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <random>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

namespace wattswath::apps {

void printJson(const nlohmann::json& j) { std::cout << j.dump(2) << std::endl; }

CLI::Option* addVehicleOption(CLI::App* cmd, std::string& path) {
  return cmd->add_option("--vehicle", path, "Vehicle description (JSON, e.g. data/vehicles/iris.json)")
      ->required()
      ->check(CLI::ExistingFile);
}

CLI::Option* addJsonFlag(CLI::App* cmd, bool& json) {
  return cmd->add_flag("--json", json, "Print one JSON object on stdout instead of text");
}

void addAreaSelectOptions(CLI::App* cmd, std::string& layer, std::string& where) {
  cmd->add_option("--layer", layer, "area files GDAL reads (GeoJSON, KML/KMZ, GeoPackage, Shapefile, GPX, ...): read only this layer");
  cmd->add_option("--where", where, "area files GDAL reads (all but WKT, QGC and Mission Planner files): read only features matching this OGR SQL filter, e.g. \"name = 'field 3'\"");
}

std::string formatNumber(double x) {
  std::ostringstream os;
  os.precision(10);
  os << x;
  return os.str();
}

std::string fixedText(double v, int precision) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(precision);
  os << v;
  return os.str();
}

void addLogReadOptions(CLI::App* cmd, logs::LogReadOptions& o) {
  cmd->add_option("--from", o.from_s, "Keep samples from this time on [s, log clock: autopilot boot time]");
  cmd->add_option("--to", o.to_s, "Keep samples up to this time [s, log clock]");
  cmd->add_flag("--airborne", o.airborne_only, "Keep only the airborne part (first take-off to last landing)");
  cmd->add_flag("--lenient", o.lenient,
                "Read past corrupt or truncated parts of .bin/.ulg files (each skip is listed as a warning)");
  cmd->add_option("--battery-instance", o.battery_instance,
                  "Battery instance to use (default: the first with a voltage above 1 V)")
      ->check(CLI::Range(0, 255));
  cmd->add_option("--position-source", o.position_source,
                  "Position message/topic: XKF1, NKF1, NKF6, EKF1 (.bin) or vehicle_local_position (.ulg)");
  cmd->add_option("--airborne-current", o.airborne.current_threshold_a,
                  "Current above which the vehicle counts as flying where no take-off/landing is logged [A]")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-gap", o.max_gap_s,
                  "Longest time between two samples; a longer gap (logger stopped, two flights) is refused [s]")
      ->check(CLI::Range(1e-3, 1e7));
}

void progress(const std::string& message) { std::cerr << message << std::endl; }

namespace {

// [-] tries at a fresh random temporary name before giving up (each collides with p = 2^-64).
constexpr int kTemporaryTries = 16;

// The temporary being written, for the signal handler (a fixed buffer: a handler may not allocate).
char g_temporary[4096];
volatile std::sig_atomic_t g_temporary_open = 0;
constexpr int kCleanedSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ};

extern "C" void removeTemporaryAndReraise(int sig) {
  if (g_temporary_open) ::unlink(g_temporary);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

// While alive, Ctrl-C, termination, hang-up or the file-size limit (SIGXFSZ) remove the temporary
// before the process dies as the signal says. Signals the program ignores stay ignored.
class TemporaryGuard {
 public:
  TemporaryGuard() {
    for (std::size_t k = 0; k < std::size(kCleanedSignals); ++k) {
      struct sigaction a {};
      a.sa_handler = removeTemporaryAndReraise;
      sigemptyset(&a.sa_mask);
      ::sigaction(kCleanedSignals[k], nullptr, &old_[k]);
      if (old_[k].sa_handler == SIG_DFL) ::sigaction(kCleanedSignals[k], &a, nullptr);
    }
  }
  ~TemporaryGuard() {
    g_temporary_open = 0;
    for (std::size_t k = 0; k < std::size(kCleanedSignals); ++k) ::sigaction(kCleanedSignals[k], &old_[k], nullptr);
  }
  TemporaryGuard(const TemporaryGuard&) = delete;
  TemporaryGuard& operator=(const TemporaryGuard&) = delete;

 private:
  struct sigaction old_[std::size(kCleanedSignals)] {};
};

// Creates `<target>.tmp.<16 random hex digits>` exclusively (O_CREAT | O_EXCL: never an existing
// file, never through a planted symlink), mode 0666 less the umask. Returns its descriptor.
int createTemporary(const std::filesystem::path& target, std::filesystem::path& tmp) {
  std::random_device rd;  // the kernel's getrandom: names nobody can predict
  for (int attempt = 0; attempt < kTemporaryTries; ++attempt) {
    char suffix[17];
    std::snprintf(suffix, sizeof suffix, "%08x%08x", rd(), rd());
    tmp = target.string() + ".tmp." + suffix;
    const bool named = tmp.native().size() < sizeof g_temporary;  // else no cleanup on signals
    if (named) std::memcpy(g_temporary, tmp.c_str(), tmp.native().size() + 1);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) {
      g_temporary_open = named;
      return fd;
    }
    if (errno != EEXIST) {
      throw std::runtime_error(target.string() + ": cannot write (" + tmp.string() + " could not be created: " +
                               std::strerror(errno) + ")");
    }
  }
  throw std::runtime_error(target.string() + ": cannot write (" + std::to_string(kTemporaryTries) +
                           " fresh temporary names beside it already existed)");
}

// Writes all of `text` to `fd` and flushes it to the disk; returns an error text (empty: done).
std::string writeAll(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return std::strerror(errno);
    done += static_cast<std::size_t>(w);
  }
  if (::fsync(fd) != 0) return std::strerror(errno);
  return {};
}

}  // namespace

void writeTextFileAtomic(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  // Renaming over a device, FIFO or folder would replace it with a plain file (seen: /dev/null).
  if (fs::exists(fs::symlink_status(target, ec)) && !fs::is_regular_file(fs::symlink_status(target, ec))) {
    throw std::runtime_error(path + ": exists and is not a regular file; expected a file path to write");
  }
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  fs::path tmp;
  const TemporaryGuard guard;
  const int fd = createTemporary(target, tmp);
  std::string error = writeAll(fd, text);
  if (::close(fd) != 0 && error.empty()) error = std::strerror(errno);
  if (error.empty()) {
    fs::rename(tmp, target, ec);  // replaces the name itself: a symlink there is not followed
    if (!ec) g_temporary_open = 0;
    if (ec) error = "cannot rename " + tmp.string() + " into place: " + ec.message();
  }
  if (!error.empty()) {
    fs::remove(tmp, ec);
    throw std::runtime_error(path + ": write failed (" + error + ")");
  }
}

CLI::Option* addForceFlag(CLI::App* cmd, bool& force) {
  return cmd->add_flag("--force", force, "Replace output files that already exist");
}

void checkWritable(const std::string& path, bool force, const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target(path);
  if (path.empty()) throw std::runtime_error("output path is empty, expected a file name");
  if (fs::is_directory(target, ec)) throw std::runtime_error(path + ": is a folder, expected an output file name");
  if (!fs::exists(target, ec)) return;
  if (!fs::is_regular_file(target, ec)) throw std::runtime_error(path + ": exists and is not a regular file");
  for (const auto& in : inputs) {
    if (fs::equivalent(target, fs::path(in), ec)) {
      throw std::runtime_error(path + ": is also an input file; refusing to overwrite an input, choose another output");
    }
  }
  if (!force) throw std::runtime_error(path + ": already exists; use --force to replace it");
}

}  // namespace wattswath::apps
