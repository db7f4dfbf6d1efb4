#pragma once
// Internal to logs/src: what the DataFlash and ULog readers (dataflash_log.cpp, ulog_log.cpp) hand
// to the common assembly into a FlightLog (autopilot_log.cpp), and the helpers they share.
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wattswath/logs/autopilot_log.hpp"

namespace wattswath::logs::detail {

constexpr double kPi = 3.14159265358979323846;
inline const double kNaN = std::numeric_limits<double>::quiet_NaN();

/// `x` written with `precision` significant digits.
std::string num(double x, int precision = 6);

/// One battery series: times [s], voltage [V] and current [A].
struct Battery {
  std::string label;          ///< where it came from, for messages and metadata
  std::string voltage_field;  ///< message and field of the voltage, e.g. "BAT.Volt", "battery_status[0].voltage_v"
  std::string current_field;  ///< message and field of the current, e.g. "BAT.Curr"
  int instance = 0;           ///< battery instance of the log
  std::vector<double> t, v, i;  ///< [s], [V], [A]
};

/// What a format-specific extractor hands to the common assembly.
struct Raw {
  std::string format, firmware, vehicle;    ///< "dataflash" or "ulog", firmware and vehicle descriptions
  Battery battery;                          ///< the battery series used
  std::vector<std::string> battery_others;  ///< other instances found, not used
  std::string position_source;              ///< where the positions came from
  std::string position_message;             ///< message or topic of the positions, e.g. "XKF1", "vehicle_local_position[0]"
  std::array<std::string, 3> pos_fields, vel_fields, acc_fields;  ///< log field of ENU x, y, z of each
  std::vector<double> pt, yaw;              ///< [s] position times, [rad] ENU yaw
  std::vector<Eigen::Vector3d> pos, vel, acc;  ///< [m], [m/s], [m/s^2] ENU at the position times
  bool has_acc = false;                     ///< acc was logged (else derived from vel)
  std::vector<LandedChange> landed;         ///< landed-state changes
  std::string landed_source;                ///< where they came from
  std::vector<LogEvent> events;             ///< events for the timeline
  std::map<std::string, std::string> meta;  ///< metadata so far
  bool has_origin = false;                  ///< the EKF origin of the positions is known geodetically
  double origin_lat = 0.0, origin_lon = 0.0, origin_alt = 0.0;  ///< [deg], [deg], [m] that origin
  std::vector<std::string> warnings;        ///< warnings so far
};

/// Takes (`lat` [deg], `lon` [deg], `alt` [m]) as `raw`'s geodetic EKF origin when lat and lon are
/// finite, in range and not both 0 (an origin not yet set); a non-finite `alt` counts as 0. Returns
/// whether it did.
bool setOrigin(Raw& raw, double lat, double lon, double alt);

/// Median of `x` (NaN when empty).
double median(std::vector<double> x);


/// Checks every battery and position value of `raw` against the canonical CSV reader's bounds
/// (tol::kLogMaxMagnitude, tol::kLogMinCurrent; positions and velocities finite), so that a log
/// read from a .bin/.ulg converts to a CSV that reads back. Strict: throws std::runtime_error
/// naming `source`, the message and field, the time, the value and the bound; lenient: drops the
/// offending samples and adds one warning per series. Called after non-increasing times are dropped.
void validateRaw(Raw& raw, const std::string& source, bool lenient);

/// Throws std::runtime_error naming `source`, the velocity field and the time when an
/// acceleration derived from the velocities (raw.has_acc false) is beyond tol::kLogMaxMagnitude.
void validateDerivedAcceleration(const Raw& raw, const std::string& source);

/// The FlightLog of `raw`: battery sample times, position, velocity, acceleration and yaw
/// interpolated to them, airborne windows, the events in time order, metadata; the time window of `opt` applied. Throws
/// std::runtime_error naming `source` when there are too few samples or they do not overlap.
FlightLog assemble(Raw raw, const std::string& source, const LogReadOptions& opt);

}  // namespace wattswath::logs::detail
