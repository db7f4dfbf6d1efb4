#pragma once
/// @file log_inputs.hpp
/// Flight logs read for replay, diagnose and fit, each checked first as a measurement of a flying
/// multirotor (calibration/measurement_check.hpp): refused with an error naming the current when
/// the power cannot be the vehicle's (unless --trust-power), cut or refused when the position
/// estimate diverged. What was found goes into the command's output, text and JSON.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "wattswath/calibration/replay.hpp"
#include "wattswath/logs/autopilot_log.hpp"

namespace wattswath::apps {

/// What the measurement checks of one command found, over all its logs.
struct MeasurementReport {
  bool trust_power = false;         ///< --trust-power was given
  nlohmann::json logs = nlohmann::json::array();  ///< one object per log: power, position, notes
  std::vector<std::string> lines;   ///< what the text output states (cuts, powers used only by --trust-power)

  /// The report as the "measurement" object of a command's JSON output.
  nlohmann::json toJson() const;
  /// Prints `lines` on stdout, one "note: ..." line each.
  void print() const;
};

/// Adds `--trust-power` (use a measured power the checks find implausible, stated in the output) to `cmd`.
CLI::Option* addTrustPowerFlag(CLI::App* cmd, bool& trust);

/// Checks `log` (read from `path`) against `vehicle` as readCheckedLogs does: cuts a diverging
/// position estimate, throws std::runtime_error "PATH: ..." for an unusable position or (unless
/// `report.trust_power`) an implausible power, and records every finding in `report`.
void checkLog(logs::FlightLog& log, const std::string& path, const energy::Vehicle& vehicle, MeasurementReport& report);

/// Reads each of `paths` (logs::readFlightLog), checks it against `vehicle` and prepares it for
/// replay. Throws std::runtime_error "FILE: ..." when the position estimate is unusable, or when the
/// measured power is implausible and `report.trust_power` is false (naming the current and what
/// was seen, and --trust-power); records every finding in `report`.
std::vector<calibration::PreparedLog> readCheckedLogs(const std::vector<std::string>& paths,
                                                      const logs::LogReadOptions& read,
                                                      const energy::Vehicle& vehicle, MeasurementReport& report);

/// Throws std::runtime_error naming both files when two of `paths` hold the same bytes (one flight
/// given twice, under two names): a fit would count it twice, a leave-one-flight-out test would
/// test it on itself. `test_from` is the index from which `paths` are test logs (paths.size():
/// none), for the message.
void checkDistinctLogs(const std::vector<std::string>& paths, std::size_t test_from);

/// A log of a flown mission, read for calibrate and replay --mission, with what was compared.
struct MissionLog {
  logs::FlightLog log;  ///< the samples compared with the mission's prediction
  std::string note;     ///< which part of the log that is and why (empty: the log as given, a CSV)
  nlohmann::json window;  ///< {"from_s", "to_s", "source", "note"}: the part compared, on the log's clock
};

/// Reads a log of a flown mission. A DataFlash or ULog log given without --from / --to / --airborne
/// is cut to its mission span (logs::missionSpan: from the switch into AUTO / AUTO_MISSION, where
/// the take-off command runs, to the landing), as a prediction from the mission file counts; with
/// no such switch logged, to its airborne part (the take-off delay is then counted from lift-off),
/// or kept whole when no airborne part is found. The note says which. The sample-gap check
/// (`read.max_gap_s`) applies to the part kept.
MissionLog readMissionLog(const std::string& path, const logs::LogReadOptions& read);

}  // namespace wattswath::apps
