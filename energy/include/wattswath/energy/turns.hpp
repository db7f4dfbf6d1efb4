#pragma once
/// @file turns.hpp
/// The two corner strategies of Marins et al. Sec. V-B (Eq. 12-16) for two straight branches of equal
/// length meeting at an interior angle beta: (1) sharp stop - brake to rest at the vertex, yaw
/// (pi - beta) in place at the maximum yaw rate, accelerate down the next branch; (2) rounded - keep
/// one constant speed v, overshoot the vertex and loop round on a circle of radius R = v / omega_max,
/// turning (pi + beta), so that the vertex is still covered; the path is longer by Eq. 15.

#include <cmath>
#include <optional>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/optimal_speed.hpp"
#include "wattswath/energy/profile.hpp"

namespace wattswath::energy {

/// [rad] smallest interior angle compared (0.5 deg): the rounded turn overshoots the vertex by
/// R cot(beta/2) on each branch, 115 R at 1 deg and without bound as beta -> 0.
inline constexpr double kMinTurnAngle = 0.5 * M_PI / 180.0;

/// The rounded turn's overshoot past the vertex on each branch, R cot(beta/2) [m], for `radius` [m]
/// and `beta` [rad] in (0, pi].
double roundedOvershoot(double radius, double beta);

/// Extra length of the rounded path over the two branches, Marins Eq. 15 [m]:
/// 2 R (1 + cos beta) / sin beta + R (pi + beta), written with (1 + cos b)/sin b = cot(b/2) so that
/// beta = pi (no turn) is well defined. `radius` [m], `beta` [rad] in (0, pi].
double roundedExtraLength(double radius, double beta);

/// Options of the comparison, with their allowed ranges.
struct TurnSettings {
  std::optional<double> sharp_speed;    ///< [m/s] cruise speed of both branches of the sharp stop, in (0, v_max]; default: optimalCruiseSpeed of one stop-to-stop branch
  std::optional<double> rounded_speed;  ///< [m/s] constant speed of the rounded path, in (0, v_max]; default: the speed minimising the rounded path's energy (its length depends on the speed through R)
  bool rounded_from_rest = false;       ///< true: the rounded path also starts and ends at rest, like the sharp stop; false: Marins Eq. 16 (constant speed throughout, no acceleration or braking)
  CruiseSpeedSettings search;           ///< settings of the speed searches
};

/// Strategy 1 of Marins Sec. V-B: stop at the vertex and turn in place (Eq. 12-14).
struct SharpStopTurn {
  double speed = 0.0;        ///< [m/s] cruise speed of each branch
  double leg_energy = 0.0;   ///< [J] energy of one branch (stop to stop)
  double turn_energy = 0.0;  ///< [J] energy of the turn in place, (pi - beta) / omega_max at hover power (Eq. 14)
  double energy = 0.0;       ///< [J] total, 2 legs + turn (Eq. 12)
  double time = 0.0;         ///< [s] total time
  Breakdown breakdown;       ///< total energy by effect and phase
};

/// Strategy 2 of Marins Sec. V-B: constant speed on the longer, rounded path (Eq. 15-16).
struct RoundedTurn {
  double speed = 0.0;         ///< [m/s] constant speed
  double radius = 0.0;        ///< [m] turn radius v / omega_max
  double path_length = 0.0;   ///< [m] L2 = 2 d + Eq. 15
  double extra_length = 0.0;  ///< [m] L2 - 2 d (Eq. 15)
  double energy = 0.0;        ///< [J] total (Eq. 16 when not from rest)
  double time = 0.0;          ///< [s] total time
  Breakdown breakdown;        ///< total energy by effect and phase
};

/// Both strategies and the saving of the rounded one.
struct TurnComparison {
  SharpStopTurn sharp_stop;  ///< strategy 1
  RoundedTurn rounded;       ///< strategy 2
  double saving_pct = 0.0;   ///< [%] 100 (E1 - E2) / E1: positive when the rounded turn saves energy (Table V)
};

/// Energy of the rounded path for branches of `leg_length` [m], angle `beta` [rad] flown at `speed` [m/s]
/// with yaw rate `max_yaw_rate` [rad/s]; `from_rest` adds acceleration from and braking to rest.
/// Throws std::invalid_argument when the path cannot be flown (e.g. too short to reach `speed` from rest).
RoundedTurn roundedTurn(const EnergyModel& model, double leg_length, double beta, double speed,
                        const ProfileLimits& limits, double max_yaw_rate, bool from_rest);

/// Energy of the sharp stop for branches of `leg_length` [m] at cruise `speed` [m/s], angle `beta` [rad].
SharpStopTurn sharpStopTurn(const EnergyModel& model, double leg_length, double beta, double speed,
                            const ProfileLimits& limits, double max_yaw_rate);

/// Compares the two strategies for branches of `leg_length` [m] (> 0) meeting at interior angle `beta`
/// [rad] in [kMinTurnAngle, pi], speeds at most `v_max` [m/s], yaw rate `max_yaw_rate` [rad/s]. Throws
/// std::invalid_argument naming the value when an input is out of range.
TurnComparison compareTurnStrategies(const EnergyModel& model, double leg_length, double beta,
                                     const ProfileLimits& limits, double max_yaw_rate, double v_max,
                                     const TurnSettings& settings = {});

}  // namespace wattswath::energy
