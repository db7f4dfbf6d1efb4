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

/// Reads each of `paths` (logs::readFlightLog), checks it against `vehicle` and prepares it for
/// replay. Throws std::runtime_error "FILE: ..." when the position estimate is unusable, or when the
/// measured power is implausible and `report.trust_power` is false (naming the current and what
/// was seen, and --trust-power); records every finding in `report`.
std::vector<calibration::PreparedLog> readCheckedLogs(const std::vector<std::string>& paths,
                                                      const logs::LogReadOptions& read,
                                                      const energy::Vehicle& vehicle, MeasurementReport& report);

}  // namespace wattswath::apps
