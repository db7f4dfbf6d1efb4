#pragma once
/// @file spiral_case.hpp
/// The spiral-coverage case of Marins, Cabreira & Ferreira (Section V-A): reconstruct the spiral
/// over a rectangle from the E-Spiral camera settings, give it the paper's speeds and score it
/// with the closed-form model. Shared by `wattswath reproduce` and its regression test.

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/path.hpp"

namespace wattswath::apps {

/// Speeds and limits of one variant of the case.
struct SpiralCaseSettings {
  double cruise_speed = 8.0;     ///< [m/s] cruise on legs at least long_leg long
  double short_leg_speed = 8.0;  ///< [m/s] cruise on shorter legs
  double long_leg = 0.0;         ///< [m] legs shorter than this cruise at short_leg_speed
  double corner_speed = 4.4;     ///< [m/s] constant speed in the curves (55 % of 8 m/s)
  double acceleration = 1.0;     ///< [m/s^2] acceleration and braking magnitude
  double yaw_rate = 2.1;         ///< [rad/s] omega_max; curves have radius corner_speed / yaw_rate
  double corner_radius = 4.4 / 2.1;  ///< [m] radius of the curves

  /// Table III: 8 m/s, 4.4 m/s curves, 1 m/s^2, the vehicle's omega_max.
  static SpiralCaseSettings table3(const energy::Vehicle& v);
  /// Table IV (corrected): 1.2 m/s^2, 4 m/s curves of radius 4 / omega_max, 7 m/s on legs under
  /// 100 m, 8 m/s on longer ones (the paper gives no exact values; see docs/reproduction.md).
  static SpiralCaseSettings table4(const energy::Vehicle& v);
};

/// The reconstructed path and its energy.
struct SpiralCaseResult {
  geometry::CoveragePath path;  ///< the spiral with rounded corners
  energy::Breakdown breakdown;  ///< energy by effect and phase, time and length
  double spacing = 0.0;         ///< [m] distance between laps (E-Spiral camera)
  int laps = 0;                 ///< offset laps of the spiral
  int pieces = 0;               ///< constant-acceleration pieces of the profile
  double coverage = 0.0;        ///< [-] covered fraction of the area (geometry::checkCoverage)
};

/// Builds the spiral over `area` (E-Spiral camera: 10 m, 100 deg, 10 % overlap; starting on a long
/// side, counter-clockwise), gives it `settings`' speeds (start and end at rest) and scores it with
/// energy::marinsModel(vehicle). Throws std::runtime_error when the area does not give one cell.
SpiralCaseResult runSpiralCase(const geometry::PolygonWithHoles& area, const energy::Vehicle& vehicle,
                               const SpiralCaseSettings& settings);

}  // namespace wattswath::apps
