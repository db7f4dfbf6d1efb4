#pragma once
/// @file cli.hpp
/// Shared plumbing of the wattswath command-line tool: command registration, output, errors.
/// Each subcommand lives in its own apps/cmd_*.cpp and exposes a register function.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "wattswath/logs/autopilot_log.hpp"

namespace wattswath::report {
class HtmlReport;
}

namespace wattswath::apps {

/// Prints `j` as one JSON object on stdout (the --json contract).
void printJson(const nlohmann::json& j);

/// Adds the common `--vehicle FILE` option (required) to `cmd`, storing into `path`.
CLI::Option* addVehicleOption(CLI::App* cmd, std::string& path);

/// CLI11 check of a number > 0 whose message names the value ("must be > 0, got 0"; CLI11's own
/// PositiveNumber printed its range up to DBL_MAX in 300 digits).
extern const CLI::Validator kPositive;

/// CLI11 check of a number >= 0, worded as kPositive.
extern const CLI::Validator kNonNegative;

/// Adds the common `--json` flag to `cmd`.
CLI::Option* addJsonFlag(CLI::App* cmd, bool& json);

/// `x` with 10 significant digits (for messages naming an offending value).
std::string formatNumber(double x);

/// `v` with exactly `precision` decimals (fixed notation), e.g. fixedText(0.0305, 2) = "0.03".
std::string fixedText(double v, int precision);

/// Prints a progress line on stderr (never on stdout, which --json owns).
void progress(const std::string& message);

/// Writes `text` to `path` through a temporary file and a rename, so an interrupted run never
/// leaves a half-written file; creates parent folders. The temporary `<path>.tmp.<16 random hex
/// digits>` is created exclusively (O_CREAT | O_EXCL | O_NOFOLLOW: never an existing file or a
/// planted symlink), fsync'ed, and removed when anything fails or SIGINT, SIGTERM, SIGHUP or
/// SIGXFSZ ends the program during the write. Throws std::runtime_error naming the path.
void writeTextFileAtomic(const std::string& path, const std::string& text);

/// The files of one run written as a set (issue 20). While alive, writeTextFileAtomic and
/// stageOutput write each file to its exclusive temporary and keep it there; commit() renames them
/// all into place, one after another in the same folder, only after every one was written, so a
/// failure midway leaves the previous run's files as they were. The output folder is locked
/// (flock on the folder itself, no lock file) for the set's life: a second wattswath run writing
/// into it is refused at once instead of clobbering the files. Destroyed without commit(), the
/// temporaries are removed. Throws std::runtime_error naming the folder when it is locked.
class OutputSet {
 public:
  /// Creates `dir` if needed and locks it.
  explicit OutputSet(const std::string& dir);
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  /// Keeps the written temporary `tmp` for `target` (`slot`: its signal-cleanup slot, -1 none).
  void stage(const std::string& tmp, const std::string& target, int slot);
  /// Renames every staged file into place; throws std::runtime_error naming the file when a rename fails.
  void commit();

 private:
  struct Staged {
    std::string tmp, target;
    int slot;
  };
  std::string dir_;
  std::vector<std::filesystem::path> made_;  // folders this set made, deepest first
  bool committed_ = false;  // commit() ran to its end
  int lock_fd_ = -1;
  OutputSet* previous_ = nullptr;
  std::vector<Staged> staged_;
  std::shared_ptr<void> guard_;  // the signal handlers that remove the temporaries
};

/// Writes `path` through `write(temporary path)` (a writer that makes the file itself, e.g.
/// GDAL's GeoPackage driver), staged in the current OutputSet or renamed into place at once;
/// returns `path`. The temporary is exclusive, removed on failure and on signals.
std::string stageOutput(const std::string& path, const std::function<void(const std::string&)>& write);

/// Adds the common `--report FILE.html` option (self-contained HTML report) and `--report-svg DIR`
/// (the same figures as separate .svg files) and `--force` (replace existing report files) to `cmd`.
void addReportOptions(CLI::App* cmd, std::string& html_path, std::string& svg_dir, bool& force);

/// Checks before any work that the report may be written (checkWritable on `html_path`; `svg_dir`
/// must not be a file, and the folder it is made in must exist); throws std::runtime_error naming the path.
void checkReportWritable(const std::string& html_path, const std::string& svg_dir, bool force,
                         const std::vector<std::string>& inputs = {});

/// Writes `report` to `html_path` (atomically) and, when `svg_dir` is not empty, each figure as
/// `svg_dir`/NAME.svg; prints the paths on stderr. Throws std::runtime_error naming a path it cannot write.
void writeReport(const report::HtmlReport& report, const std::string& html_path, const std::string& svg_dir = "",
                 bool force = false);

/// Adds the flight-log reading options (--from, --to, --airborne, --lenient, --battery-instance,
/// --position-source, --airborne-current, --max-gap) to `cmd`, storing into `options`. Use with logs::readFlightLog().
void addLogReadOptions(CLI::App* cmd, logs::LogReadOptions& options);
/// Adds --max-log-size [MiB] (LogReadOptions::max_file_bytes) to `cmd`; part of addLogReadOptions.
void addMaxLogSizeOption(CLI::App* cmd, logs::LogReadOptions& o);

/// Adds `--layer NAME` and `--where SQL` (which layer and features of a GIS area file GDAL reads) to `cmd`.
void addAreaSelectOptions(CLI::App* cmd, std::string& layer, std::string& where);

/// Adds the common `--force` flag (allow replacing existing output files) to `cmd`.
CLI::Option* addForceFlag(CLI::App* cmd, bool& force);

/// Checks, before any work is done, that `path` may be written: throws std::runtime_error naming
/// the path when it is a folder, when its folder does not exist (checkOutputFolder), when it
/// already exists and `force` is false ("use --force"), or
/// when it is one of `inputs` (an input is never overwritten, even with --force; an output of the
/// same run not written yet, passed among `inputs`, is refused as named twice).
void checkWritable(const std::string& path, bool force, const std::vector<std::string>& inputs = {});

/// Throws std::runtime_error naming the first missing folder of `path` when the folder `path` is
/// to be written into does not exist (or is not a folder): output files' folders are not created
/// (only plan's --out and a --report-svg folder are), so a mistyped path is an error. checkWritable
/// calls it.
void checkOutputFolder(const std::string& path);

// Register functions: one per apps/cmd_*.cpp. main.cpp calls each.
void registerEnergyCommands(CLI::App& app);    ///< hover, vopt, leg, turns (cmd_energy.cpp)
void registerReproduceCommand(CLI::App& app);  ///< reproduce (cmd_reproduce.cpp)
void registerLogCommands(CLI::App& app);       ///< replay, diagnose, fit, simulate (cmd_logs.cpp)
void registerLogFileCommands(CLI::App& app);   ///< log info, log convert (cmd_log.cpp)
void registerAreaCommands(CLI::App& app);      ///< area info (cmd_area.cpp)
void registerPlanCommand(CLI::App& app);      ///< plan (cmd_plan.cpp)
void registerEnduranceCommands(CLI::App& app); ///< endurance, models (cmd_endurance.cpp)
void registerVehicleCommands(CLI::App& app);   ///< vehicle params (cmd_vehicle.cpp)

/// Parses `--speed` text: one speed "U" or a range "FROM:TO:STEP" [m/s]; throws
/// std::invalid_argument quoting the text otherwise.
std::vector<double> parseSpeedList(const std::string& text);
void registerCoverageCommand(CLI::App& app);   ///< coverage (cmd_coverage.cpp)
void registerPredictCommand(CLI::App& app);    ///< predict (cmd_predict.cpp)
void registerCalibrateCommand(CLI::App& app);  ///< calibrate (cmd_calibrate.cpp)

}  // namespace wattswath::apps
