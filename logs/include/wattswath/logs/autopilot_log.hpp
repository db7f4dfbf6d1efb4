#pragma once
/// @file autopilot_log.hpp
/// Flight logs as users have them: ArduPilot DataFlash (.bin) and PX4 ULog (.ulg) read into the
/// same FlightLog the canonical CSV produces, plus airborne detection, time windows and one
/// dispatch function that picks the reader by the file's content.
///
/// Resampling: the battery samples define the time base. Position, velocity, acceleration and yaw
/// (yaw unwrapped first) are interpolated linearly at each battery sample time from the position
/// source's two neighbouring samples; battery values are the measured ones, never interpolated.
/// Battery samples before the first or after the last position sample are not kept; their count
/// is in metadata `battery_samples_outside_position`. Positions are local ENU (x east, y north,
/// z up) from the autopilot's EKF origin: NED x = north, y = east, z = down maps to
/// (y, x, -z).

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "wattswath/logs/flight_log.hpp"
#include "wattswath/logs/tolerances.hpp"

namespace wattswath::logs {

/// How the airborne part of a log is found.
struct AirborneSettings {
  double current_threshold_a = 5.0;  ///< [A] flying when current exceeds this (where no landed state is logged); > 0
  double merge_gap_s = 1.0;          ///< [s] windows separated by less than this are merged; >= 0
  double min_duration_s = 2.0;       ///< [s] windows shorter than this are dropped; >= 0
  double landing_extend_s = 5.0;     ///< [s] a current-based window ending at most this long before a logged landing runs up to it; >= 0
};

/// Options of the flight-log readers.
struct LogReadOptions {
  double from_s = -std::numeric_limits<double>::infinity();  ///< [s] keep samples at t >= from_s (log clock)
  double to_s = std::numeric_limits<double>::infinity();     ///< [s] keep samples at t <= to_s (log clock)
  bool airborne_only = false;  ///< keep only the span from the first airborne window's start to the last one's end
  bool lenient = false;        ///< skip corrupt or truncated parts of binary logs; each skip is listed in metadata `warnings`
  int battery_instance = -1;   ///< [-] battery instance to use; -1: the first one with a plausible voltage (> 1 V)
  std::string position_source; ///< force a position source ("XKF1", "NKF1", "NKF6", "EKF1", "vehicle_local_position"); empty: automatic
  AirborneSettings airborne;   ///< airborne detection settings
  double max_gap_s = tol::kLogMaxSampleGap;  ///< [s] longest time allowed between two samples (after the window); > 0
  long long max_file_bytes = tol::kLogMaxFileBytes;  ///< [B] largest log file read (it is read whole); > 0
};

/// A landed-state change the autopilot logged (take-off or landing event).
struct LandedChange {
  double t = 0.0;       ///< [s] time (log clock)
  bool landed = false;  ///< state from `t` on
  std::string what;     ///< which message said so, e.g. "EV 17 LAND_COMPLETE_MAYBE"
};

/// Airborne windows: where landed-state changes exist, the state from the first change on is
/// theirs; before the first change (or everywhere, when there is none) the vehicle counts as
/// airborne while `current` > settings.current_threshold_a, with crossing times interpolated
/// linearly between samples; when the first change is a landing, the last current-based window
/// ending at most landing_extend_s before it is extended to it. Windows closer than merge_gap_s are merged, shorter than
/// min_duration_s dropped. `t` [s] increasing, `current` [A] of the same length.
std::vector<TimeWindow> detectAirborne(const std::vector<double>& t, const std::vector<double>& current,
                                       const std::vector<LandedChange>& changes, const AirborneSettings& settings);

/// Reads an ArduPilot DataFlash log (.bin) from `path`.
FlightLog readDataFlashLog(const std::string& path, const LogReadOptions& options = {});
/// Reads a PX4 ULog file (.ulg) from `path`.
FlightLog readUlogLog(const std::string& path, const LogReadOptions& options = {});
/// Reads DataFlash bytes already in memory; `source` names them in messages (fuzzing, tests).
FlightLog readDataFlashBytes(std::vector<std::uint8_t> bytes, const std::string& source, const LogReadOptions& options);
/// Reads ULog bytes already in memory; `source` names them in messages (fuzzing, tests).
FlightLog readUlogBytes(std::vector<std::uint8_t> bytes, const std::string& source, const LogReadOptions& options);

/// Flight-log file formats the project reads.
enum class LogFormat { Csv, DataFlash, Ulog };

/// Format of the file at `path`, from its first bytes ("ULog" magic, 0xA3 0x95 header, else CSV).
LogFormat detectLogFormat(const std::string& path);

/// What the reader of `log` skipped or found (a truncated file, samples out of time order, a gap in
/// the positions, a log that ends in the air), one sentence each: metadata `warnings` split.
std::vector<std::string> readerWarnings(const FlightLog& log);

/// Reads a flight log of any supported format (picked by content, see detectLogFormat()) and
/// applies options.from_s / to_s / airborne_only. The one entry point for `--log FILE`.
FlightLog readFlightLog(const std::string& path, const LogReadOptions& options = {});

/// Keeps the samples of `log` inside [options.from_s, options.to_s] (and the airborne span when
/// options.airborne_only), clips log.airborne and log.events to it and records the window in
/// metadata `window`. Throws when fewer than two samples remain, naming the window and the span.
void applyTimeWindow(FlightLog& log, const LogReadOptions& options);

/// The part of an autopilot log that flew a mission, as a prediction from the mission file counts it:
/// from the take-off command (the switch into the mission mode, where a mission starting with
/// NAV_TAKEOFF runs it) to the landing.
struct MissionSpan {
  double from_s = 0.0;            ///< [s] log clock: the first switch into ArduPilot AUTO or PX4 AUTO_MISSION / AUTO_TAKEOFF
  double to_s = 0.0;              ///< [s] log clock: the landing: ArduCopter's LAND_COMPLETE, else the end of the last airborne window after from_s
  double liftoff_s = 0.0;         ///< [s] log clock: the first airborne window's start after from_s (NaN when started in the air)
  bool started_airborne = false;  ///< true when the vehicle was already flying at from_s (no take-off in the span)
  std::string from_what;          ///< what gave the start, e.g. "the switch to AUTO (3) at 54.10 s"
  std::string to_what;            ///< what gave the end, e.g. "the landing at 180.34 s"
};

/// The mission span of a DataFlash or ULog log (see MissionSpan); nullopt for a CSV (whose rows
/// are taken as given), or when the log records no switch into the mission mode followed by an
/// airborne window.
std::optional<MissionSpan> missionSpan(const FlightLog& log);

/// What cutToMission() did to a log.
struct MissionCut {
  std::string note;    ///< "FILE: compared from ... to ..." (empty: the log was left as it is)
  std::string source;  ///< "mission mode to landing", "mission mode, started in the air", "airborne part", "whole log" or empty
  double from_s = std::numeric_limits<double>::quiet_NaN();  ///< [s] log clock: start of the part kept (NaN: left as it is)
  double to_s = std::numeric_limits<double>::quiet_NaN();    ///< [s] log clock: end of the part kept (NaN: left as it is)
};

/// Cuts a DataFlash or ULog log that no time window has cut yet (no metadata `window`) to the part
/// a mission's prediction is compared with: its mission span, else its airborne part (a take-off
/// delay then counts from lift-off), else the whole log, and says which. A CSV, or a log already
/// cut, is left as it is.
MissionCut cutToMission(FlightLog& log);

/// Throws std::runtime_error naming log.source, the two times and the limit when consecutive
/// samples of `log` are more than `max_gap_s` [s] apart: the energy over such a gap (the logger
/// stopped, or two flights in one log) was not measured and must not be integrated. The readers
/// call it after the time window, so --from / --to can pick one part of such a log.
void checkSampleGaps(const FlightLog& log, double max_gap_s);

}  // namespace wattswath::logs
