#pragma once
/// @file log_io.hpp
/// The canonical flight-log CSV (../shared/formats/flight-log-csv.md): reader, writer, and the
/// derivation of velocity and acceleration when a log does not carry them.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "wattswath/logs/flight_log.hpp"
#include "wattswath/logs/tolerances.hpp"

namespace wattswath::logs {

/// How missing velocities and accelerations are derived from positions (and velocities).
/// Method: a local quadratic least-squares fit over a window of 2 * half_window + 1 samples
/// centred on each sample (Savitzky-Golay smoothing, generalised to uneven time steps); the
/// derivative of the fitted parabola at the sample is the estimate. Near the ends the window is
/// shifted inwards so it keeps its size. Velocity = d(position)/dt; acceleration = d(velocity)/dt
/// of the (given or derived) velocity.
struct DerivativeSettings {
  int half_window = 2;  ///< [samples] half width of the fitting window, range 1..50 (2 -> 5 samples)
};

/// Reads a canonical CSV flight log. Handles a UTF-8 byte-order mark and CRLF line ends; keeps
/// unknown columns verbatim; converts lat/lon/alt to local ENU metres at the first sample
/// (GeographicLib LocalCartesian on WGS84); derives velocity/acceleration when absent (`d`).
/// Throws std::runtime_error "FILE:LINE: column 'NAME': ..." for a missing required column, a
/// non-numeric or non-finite value in a used column, a value beyond tol::kLogMaxMagnitude (not
/// time, lat, lon), a row with the wrong number of fields, time that does not increase by at least
/// tol::kLogMinTimeStep, lat/lon (or origin metadata) out of range, derived velocities or
/// accelerations that are not finite, or fewer than two samples. Never drops rows. Empty cells are
/// allowed only in the optional columns yaw_rad, mass_kg, wind_x_mps, wind_y_mps (NaN: not measured).
/// A file larger than `max_file_bytes` [B] is refused before it is read.
FlightLog readCsvLog(const std::string& path, const DerivativeSettings& d = {},
                     long long max_file_bytes = tol::kLogMaxFileBytes);

/// Parses CSV text as readCsvLog does; `source` names it in messages and FlightLog::source.
FlightLog parseCsvLog(const std::string& text, const std::string& source, const DerivativeSettings& d = {});

/// Writes `log` as canonical CSV text: metadata as `# key: value` lines, then time, local
/// position, velocity, acceleration, yaw (when any sample has it), voltage and current (when
/// every sample has both), power, mass and wind (when any sample has them), then the extra
/// columns verbatim. Numbers use the shortest text that reads back to the same double.
/// Throws std::invalid_argument naming the sample when a time, position, velocity,
/// acceleration or power is not finite.
std::string writeCsvLog(const FlightLog& log);

/// Fills velocities (when `velocity`) and accelerations (when `acceleration`) of `log` from
/// positions and velocities with the smoothing of `d`; sets the *_derived flags.
void deriveKinematics(FlightLog& log, bool velocity, bool acceleration, const DerivativeSettings& d = {});

/// Parses a waypoint path (what `simulate --path` flies): "x y z" or "x,y,z" [m, local ENU] per
/// line; blank lines and '#' comments are skipped, and so is a first line that does not start with
/// a number (a header). Throws std::runtime_error "SOURCE:LINE: expected three numbers x y z [m],
/// got '...'" for anything else, for a coordinate beyond tol::kLogMaxMagnitude, and "SOURCE: a path
/// needs at least 2 waypoints"; a waypoint within 0.01 m of the previous one is an error (each is a stop).
std::vector<Eigen::Vector3d> parseWaypointPath(const std::string& text, const std::string& source);

/// Largest waypoint path file read [B] (read whole).
inline constexpr long long kMaxPathFileBytes = 64LL * 1024 * 1024;

/// Reads a waypoint path file as parseWaypointPath() does; throws naming `path` when it cannot be
/// read or is over kMaxPathFileBytes.
std::vector<Eigen::Vector3d> readWaypointPath(const std::string& path);

}  // namespace wattswath::logs
