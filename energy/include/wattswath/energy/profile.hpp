#pragma once
/// @file profile.hpp
/// Speed profiles: a flight as constant-acceleration pieces along a path (speed squared is
/// piecewise linear in arc length), with the phase each piece belongs to.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace wattswath::energy {

/// Phase of flight a piece or a log sample belongs to.
enum class Phase { Accelerate = 0, Cruise, Brake, Turn, Climb, Descent, Hover, Ground };

/// Number of phases (size of per-phase arrays).
inline constexpr int kPhaseCount = 8;

/// Lower-case name of a phase ("accelerate", "cruise", ...).
const char* toString(Phase p);

/// One constant-acceleration piece of flight. A turn in place has zero length and a yaw angle;
/// an arc has length and a yaw angle; a hover has zero length and a duration.
struct Piece {
  Phase phase = Phase::Cruise;  ///< phase this piece belongs to
  double length = 0.0;          ///< [m] distance flown along the path (0 for turn in place / hover)
  double v_start = 0.0;         ///< [m/s] speed along the path at the start
  double v_end = 0.0;           ///< [m/s] speed along the path at the end
  double duration = 0.0;        ///< [s] time; equals 2 L / (v0 + v1) when length > 0
  double heading = 0.0;         ///< [rad] ENU heading at the start (0 = east, counter-clockwise)
  double yaw_angle = 0.0;       ///< [rad] signed heading change over the piece (arcs, turns in place)
  double climb = 0.0;           ///< [m] height gained over the piece (negative: descent)
  double v_cruise = 0.0;        ///< [m/s] cruise speed of the leg the piece belongs to (for Eq. 9)

  /// Constant acceleration along the path [m/s^2] (0 for zero-length pieces).
  double acceleration() const {
    return length > 0.0 ? (v_end * v_end - v_start * v_start) / (2.0 * length) : 0.0;
  }
};

/// Instantaneous motion of the vehicle: what a power model needs at one instant.
struct MotionState {
  double t = 0.0;                                          ///< [s] time since start
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      ///< [m/s] ground velocity, ENU
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  ///< [m/s^2] acceleration, gravity removed, ENU
  double yaw_rate = 0.0;                                   ///< [rad/s] heading rate
  double heading = 0.0;                                    ///< [rad] ENU heading
  bool airborne = true;                                    ///< false on the ground (motors idle)
};

/// Motion state at time `tau` [s] into piece `p`, starting at absolute time `t0` [s].
MotionState stateAt(const Piece& p, double tau, double t0 = 0.0);

/// Limits a leg's speed profile must respect.
struct ProfileLimits {
  double acceleration = 1.0;  ///< [m/s^2] magnitude used when speeding up
  double deceleration = 1.0;  ///< [m/s^2] magnitude used when braking
};

/// Builds the accelerate / cruise / brake pieces of a straight leg of length `distance` [m]
/// entered at `v_entry`, cruising at `v_cruise` and left at `v_exit` [m/s] (Marins Eq. 6).
/// When the leg is too short to reach the cruise speed the profile is triangular (peak below
/// cruise). An entry speed above cruise brakes down to cruise first. A request that cannot be
/// flown (the speed change from entry to exit needs more distance than the leg has, negative or
/// non-finite values) throws std::invalid_argument naming the values. Zero distance with equal
/// entry and exit speeds gives an empty profile.
std::vector<Piece> buildLegProfile(double distance, double v_entry, double v_cruise, double v_exit,
                                   const ProfileLimits& limits, double heading = 0.0, double climb = 0.0);

/// Derivative of one piece's free parameters with respect to the leg's cruise speed (chain rule
/// for the optimal-speed search). Duration follows from length and speeds (2 L / (v0 + v1)).
struct PieceSensitivity {
  double length = 0.0;    ///< [m per m/s] d length / d v_cruise
  double v_start = 0.0;   ///< [-] d v_start / d v_cruise
  double v_end = 0.0;     ///< [-] d v_end / d v_cruise
  double v_cruise = 0.0;  ///< [-] d v_cruise / d v_cruise (1 for every piece of the leg)
  double climb = 0.0;     ///< [m per m/s] d climb / d v_cruise
};

/// The pieces of buildLegProfile() (same arguments, same exceptions) and, in `sensitivity`
/// (resized to match), each piece's derivative with respect to `v_cruise`. One-sided at the
/// kinks where the profile changes shape (cruise speed equal to entry/exit or to the peak).
std::vector<Piece> buildLegProfileWithSensitivity(double distance, double v_entry, double v_cruise, double v_exit,
                                                  const ProfileLimits& limits,
                                                  std::vector<PieceSensitivity>& sensitivity, double heading = 0.0,
                                                  double climb = 0.0);

/// Highest speed a leg can reach: the peak of the triangular profile from `v_entry` to `v_exit`
/// over `distance` [m/s]. Cruise speeds above it give the same profile.
double legPeakSpeed(double distance, double v_entry, double v_exit, const ProfileLimits& limits);

/// A turn in place of signed angle `angle` [rad] at yaw rate `yaw_rate` [rad/s].
Piece turnInPlace(double angle, double yaw_rate, double heading = 0.0);

/// An arc of radius `radius` [m] turning by signed `angle` [rad] at constant speed `speed` [m/s].
Piece arc(double radius, double angle, double speed, double heading = 0.0);

/// A hover of `duration` [s].
Piece hover(double duration);

/// Total time of a profile [s].
double totalTime(const std::vector<Piece>& pieces);

/// Total length of a profile [m].
double totalLength(const std::vector<Piece>& pieces);

}  // namespace wattswath::energy
