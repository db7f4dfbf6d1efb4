#pragma once
/// @file flight_log.hpp
/// The in-memory flight log every reader produces (canonical CSV, ArduPilot DataFlash, PX4 ULog)
/// and every replay, diagnosis and fit consumes. Format: ../shared/formats/flight-log-csv.md.

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace wattswath::logs {

/// One measured sample. Optional quantities are NaN when the log does not have them.
struct LogSample {
  double t = 0.0;                                           ///< [s] time, strictly increasing
  Eigen::Vector3d position = Eigen::Vector3d::Zero();       ///< [m] local ENU (z up)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();       ///< [m/s] ground velocity ENU
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();   ///< [m/s^2] gravity removed, ENU
  double yaw = std::numeric_limits<double>::quiet_NaN();    ///< [rad] ENU heading, NaN if absent
  double voltage = std::numeric_limits<double>::quiet_NaN();  ///< [V] battery voltage, NaN if absent
  double current = std::numeric_limits<double>::quiet_NaN();  ///< [A] battery current, NaN if absent
  double power = std::numeric_limits<double>::quiet_NaN();    ///< [W] electrical power drawn
  double mass = std::numeric_limits<double>::quiet_NaN();     ///< [kg] vehicle mass, NaN if absent
  Eigen::Vector2d wind = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());  ///< [m/s]
};

/// A closed time interval, e.g. one airborne part of a flight.
struct TimeWindow {
  double begin = 0.0;  ///< [s] start time (log clock)
  double end = 0.0;    ///< [s] end time (log clock), >= begin
  /// True when time `t` [s] (log clock) is in the window, its ends included.
  bool contains(double t) const { return t >= begin && t <= end; }
};

/// Something the autopilot logged at a time: a mode change, an event, a mission item, a message.
struct LogEvent {
  double t = 0.0;    ///< [s] time (log clock)
  std::string kind;  ///< "mode", "event", "landed", "mission_item", "message"
  std::string text;  ///< human-readable description, e.g. "RTL (6)"
};

/// A whole flight: samples plus where they came from and what was derived.
struct FlightLog {
  std::string source;                              ///< file the log was read from
  std::string format;                              ///< "csv", "dataflash", "ulog", "simulated"
  std::map<std::string, std::string> metadata;     ///< `# key: value` comments and reader facts
  std::vector<LogSample> samples;                  ///< in time order
  bool has_geodetic_origin = false;                ///< true when the ENU origin is known geodetically (lat/lon columns, or an autopilot log's EKF origin)
  double origin_lat_deg = 0.0;                     ///< [deg] ENU origin latitude (when geodetic)
  double origin_lon_deg = 0.0;                     ///< [deg] ENU origin longitude (when geodetic)
  double origin_alt_m = 0.0;                       ///< [m] ENU origin altitude (when geodetic)
  bool velocity_derived = false;                   ///< velocities computed from positions
  bool acceleration_derived = false;               ///< accelerations computed from velocities
  std::vector<std::string> extra_columns;          ///< unknown columns, kept in file order
  std::vector<std::vector<std::string>> extra_values;  ///< extra_values[row][col], verbatim
  std::vector<TimeWindow> airborne;                ///< airborne windows found by the reader (may be empty)
  std::vector<LogEvent> events;                    ///< modes, events, mission items (autopilot logs)

  /// Duration from first to last sample [s].
  double duration() const { return samples.size() < 2 ? 0.0 : samples.back().t - samples.front().t; }
};

}  // namespace wattswath::logs
