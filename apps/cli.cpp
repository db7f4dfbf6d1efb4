#include "cli.hpp"
#include "output_journal.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
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
#include <sys/file.h>
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

namespace {
// A CLI11 validator of a finite number against `ok`, saying "<expected>, got <value>" otherwise.
CLI::Validator numberCheck(const std::string& expected, bool (*ok)(double)) {
  return CLI::Validator(
      [expected, ok](std::string& text) -> std::string {
        double x = 0.0;
        if (!CLI::detail::lexical_cast(text, x) || !std::isfinite(x)) return "expected a number " + expected + ", got " + text;
        return ok(x) ? std::string() : "expected a number " + expected + ", got " + text;
      },
      expected == "> 0" ? "POSITIVE" : "NONNEGATIVE");
}
}  // namespace

const CLI::Validator kPositive = numberCheck("> 0", [](double x) { return x > 0.0; });
const CLI::Validator kNonNegative = numberCheck(">= 0", [](double x) { return x >= 0.0; });

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
      ->check(kPositive);
  cmd->add_option("--max-gap", o.max_gap_s,
                  "Longest time between two samples; a longer gap (logger stopped, two flights) is refused [s]")
      ->check(CLI::Range(1e-3, 1e7));
  addMaxLogSizeOption(cmd, o);
}

void addMaxLogSizeOption(CLI::App* cmd, logs::LogReadOptions& o) {
  cmd->add_option_function<double>(
         "--max-log-size", [&o](double mib) { o.max_file_bytes = static_cast<long long>(mib * 1048576.0); },
         "Largest log file read, read whole [MiB] (default 512: about 1.5 GB of memory)")
      ->check(CLI::Range(1.0, 65536.0));
}

void progress(const std::string& message) { std::cerr << message << std::endl; }

namespace {

// [-] tries at a fresh random temporary name before giving up (each collides with p = 2^-64).
constexpr int kTemporaryTries = 16;

// The temporaries alive (being written, or written and waiting for their output set's commit), for
// the signal handler: fixed buffers, since a handler may not allocate. A path longer than a slot,
// or beyond the slots, is written but not removed on a signal.
constexpr int kTrackedTemporaries = 256;
char g_temporary[kTrackedTemporaries][1024];
volatile std::sig_atomic_t g_temporary_open[kTrackedTemporaries] = {};
constexpr int kCleanedSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ};

// The output set being written, if any (writeTextFileAtomic stages into it instead of renaming).
OutputSet* g_output_set = nullptr;

extern "C" void removeTemporaryAndReraise(int sig) {
  for (int k = 0; k < kTrackedTemporaries; ++k)
    if (g_temporary_open[k]) ::unlink(g_temporary[k]);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

// A slot naming `path` for the signal handler (-1: none free or the path too long).
int trackTemporary(const std::string& path) {
  if (path.size() >= sizeof g_temporary[0]) return -1;
  for (int k = 0; k < kTrackedTemporaries; ++k) {
    if (g_temporary_open[k]) continue;
    std::memcpy(g_temporary[k], path.c_str(), path.size() + 1);
    g_temporary_open[k] = 1;
    return k;
  }
  return -1;
}

void untrackTemporary(int slot) {
  if (slot >= 0) g_temporary_open[slot] = 0;
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
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
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

namespace {

// Puts the written temporary `tmp` (signal-cleanup `slot`) in place as `target`: staged in the
// current OutputSet, else renamed now (replacing the name itself: a symlink there is not followed).
// With a non-empty `error` (the write failed) or a failed rename, removes it and throws naming `target`.
void placeTemporary(const std::filesystem::path& tmp, const std::filesystem::path& target, int slot, std::string error) {
  std::error_code ec;
  if (error.empty() && g_output_set) {  // renamed with the rest of the set at its commit
    g_output_set->stage(tmp.string(), target.string(), slot);
    return;
  }
  if (error.empty()) {
    std::filesystem::rename(tmp, target, ec);
    if (ec) error = "cannot rename " + tmp.string() + " into place: " + ec.message();
  }
  if (!error.empty()) std::filesystem::remove(tmp, ec);
  untrackTemporary(slot);
  if (!error.empty()) throw std::runtime_error(target.string() + ": write failed (" + error + ")");
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
  fs::path tmp;
  const TemporaryGuard guard;
  const int fd = createTemporary(target, tmp);
  const int slot = trackTemporary(tmp.string());
  std::string error = writeAll(fd, text);
  if (::close(fd) != 0 && error.empty()) error = std::strerror(errno);
  placeTemporary(tmp, target, slot, error);
}

std::string stageOutput(const std::string& path, const std::function<void(const std::string&)>& write) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  fs::path tmp;
  const TemporaryGuard guard;
  ::close(createTemporary(target, tmp));  // an exclusive placeholder the writer replaces
  const int slot = trackTemporary(tmp.string());
  try {
    write(tmp.string());
  } catch (...) {  // the writer's own error, as it gave it
    fs::remove(tmp, ec);
    untrackTemporary(slot);
    throw;
  }
  placeTemporary(tmp, target, slot, "");
  return path;
}

OutputSet::OutputSet(const std::string& dir) : dir_(dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // The folders this set makes (the leaf and any missing parents), removed again if it fails.
  for (fs::path p = fs::absolute(dir, ec); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    made_.push_back(p);
    if (p == p.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  lock_fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (lock_fd_ < 0) throw std::runtime_error(dir + ": cannot open the output folder (" + std::strerror(errno) + ")");
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(lock_fd_);
    lock_fd_ = -1;
    if (err == EWOULDBLOCK)
      throw std::runtime_error(dir + ": another wattswath run is writing into this folder (it holds its lock); wait "
                               "for it to finish or choose another output folder");
    throw std::runtime_error(dir + ": cannot lock the output folder (" + std::strerror(err) + ")");
  }
  // A commit of an earlier run cut short by a crash is completed first (its journal says which files).
  const int completed = completeInterruptedCommit(dir);
  if (completed > 0) {
    progress(dir + ": completed the interrupted commit of an earlier run (" + std::to_string(completed) +
             " file(s) renamed into place from its journal " + kCommitJournal + ")");
  }
  previous_ = g_output_set;
  g_output_set = this;
  guard_ = std::shared_ptr<void>(new TemporaryGuard, [](void* g) { delete static_cast<TemporaryGuard*>(g); });
}

OutputSet::~OutputSet() {
  std::error_code ec;
  for (const auto& f : staged_) {
    std::filesystem::remove(f.tmp, ec);
    untrackTemporary(f.slot);
  }
  g_output_set = previous_;
  guard_.reset();
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the lock
  // A run that failed before committing leaves no folder it made (remove() takes only an empty one).
  if (!committed_)
    for (const auto& p : made_) std::filesystem::remove(p, ec);
}

void OutputSet::stage(const std::string& tmp, const std::string& target, int slot) { staged_.push_back({tmp, target, slot}); }

void OutputSet::commit() {
  namespace fs = std::filesystem;
  std::error_code ec;
  // Every staged file is listed in the folder's journal (flushed) before any is renamed, so a crash
  // midway is completed by the next run into the folder: files inside it by name, files elsewhere
  // (a --report path) by absolute path.
  const fs::path dir = fs::absolute(dir_, ec).lexically_normal();
  std::vector<std::pair<std::string, std::string>> journaled;
  std::vector<fs::path> elsewhere;  // the other folders written into, flushed before the journal goes
  for (const auto& f : staged_) {
    const fs::path t = fs::absolute(f.target, ec).lexically_normal(), tmp = fs::absolute(f.tmp, ec).lexically_normal();
    if (t.parent_path() == dir && tmp.parent_path() == dir) {
      journaled.emplace_back(tmp.filename().string(), t.filename().string());
    } else {
      journaled.emplace_back(tmp.string(), t.string());
      if (std::find(elsewhere.begin(), elsewhere.end(), t.parent_path()) == elsewhere.end()) elsewhere.push_back(t.parent_path());
    }
  }
  if (!journaled.empty()) writeCommitJournal(dir_, journaled);
  for (std::size_t k = 0; k < staged_.size(); ++k) {
    std::filesystem::rename(staged_[k].tmp, staged_[k].target, ec);
    if (ec) {
      const std::string msg = staged_[k].target + ": write failed (cannot rename " + staged_[k].tmp + " into place: " +
                              ec.message() + "); " + std::to_string(k) + " of the " + std::to_string(staged_.size()) +
                              " files of this run were already in place";
      staged_.erase(staged_.begin(), staged_.begin() + static_cast<long>(k));
      removeCommitJournal(dir_);
      throw std::runtime_error(msg);
    }
    untrackTemporary(staged_[k].slot);
  }
  for (const auto& folder : elsewhere) syncFolder(folder.string());
  syncFolder(dir_);
  removeCommitJournal(dir_);
  staged_.clear();
  committed_ = true;
}

CLI::Option* addForceFlag(CLI::App* cmd, bool& force) {
  return cmd->add_flag("--force", force, "Replace output files that already exist");
}

void checkOutputFolder(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty() || fs::is_directory(parent, ec)) return;
  // The first folder of the path that is missing, which a typo most likely made.
  fs::path missing = parent;
  for (fs::path p = parent; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing = p;
    if (p == p.parent_path()) break;
  }
  if (fs::exists(missing, ec)) throw std::runtime_error(path + ": " + missing.string() + " is not a folder, expected a folder to write into");
  throw std::runtime_error(path + ": the folder " + missing.string() + " does not exist, expected an existing folder (output "
                           "folders are not created, so a mistyped path is not written somewhere new: create it first)");
}

void checkWritable(const std::string& path, bool force, const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target(path);
  if (path.empty()) throw std::runtime_error("output path is empty, expected a file name");
  if (fs::is_directory(target, ec)) throw std::runtime_error(path + ": is a folder, expected an output file name");
  checkOutputFolder(path);
  // The same name twice in one run (an input, or another output not written yet): one would be lost.
  const fs::path canonical = fs::weakly_canonical(target, ec);
  for (const auto& in : inputs) {
    std::error_code ec2;
    if (!in.empty() && !ec && fs::weakly_canonical(fs::path(in), ec2) == canonical && !ec2) {
      if (fs::exists(target, ec2)) {
        throw std::runtime_error(path + ": is also an input file; refusing to overwrite an input, choose another output");
      }
      throw std::runtime_error(path + ": is named twice in this run (also as " + in +
                               ", another output); one would overwrite the other, choose another output");
    }
  }
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
