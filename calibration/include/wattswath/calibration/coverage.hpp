#pragma once
/// @file coverage.hpp
/// What kind of flying a calibration saw, and whether a mission to predict asks for the same kind:
/// a calibration fitted on flights through fast waypoints says little about stops, and one fitted
/// at 4-6 m/s little about 10 m/s. `predict` says so and shows the spread (docs/validation.md 5.2).

#include <string>
#include <vector>

#include "wattswath/mission/autopilot.hpp"
#include "wattswath/mission/flight.hpp"

namespace wattswath::calibration {

/// The flying a mission asks of the autopilot's behaviour model.
struct MissionKind {
  int stop_waypoints = 0;     ///< waypoints with a hold time (the vehicle stops there)
  int fast_waypoints = 0;     ///< waypoints without one (flown through, or stopped at by the 3.x rule)
  double speed_lo_mps = 0.0;  ///< [m/s] slowest horizontal speed commanded on a leg (0: no leg)
  double speed_hi_mps = 0.0;  ///< [m/s] fastest horizontal speed commanded on a leg (0: no leg)
  /// [m] the median horizontal leg between waypoints; joined kinds keep the lowest and the highest
  /// of their medians (0: no leg, or not recorded)
  double leg_lo_m = 0.0;
  double leg_hi_m = 0.0;      ///< [m] see leg_lo_m
  double turn_hi_deg = -1.0;  ///< [deg] sharpest turn at a waypoint without a hold time (-1: none, or not recorded)
  double climb_hi_m = -1.0;   ///< [m] largest height change on a leg between waypoints (-1: none, or not recorded)
  int circles = -1;           ///< NAV_LOITER_TURNS items flown (-1: not recorded)
};

/// The kind of `steps` flown by `autopilot`: its waypoints by hold time, and the horizontal speed
/// in force on each leg (a DO_CHANGE_SPEED, else WPNAV_SPEED or MPC_XY_CRUISE).
MissionKind missionKind(const std::vector<mission::NavStep>& steps, const mission::AutopilotConfig& autopilot);

/// `a` and `b` together (counts added, speed ranges joined).
MissionKind combine(const MissionKind& a, const MissionKind& b);

/// Why `mission` is outside what `calibrated` flew, one sentence each (empty: inside): waypoint
/// kinds the calibration never flew, speeds more than 10 % beyond its range, a median leg under half
/// its lowest median leg (one short leg does not make a mission of short legs), turns through
/// waypoints more than 20 deg sharper than its sharpest, height changes on legs above twice (and
/// 5 m more than) its largest, circles (NAV_LOITER_TURNS) it never flew. A quantity not recorded is
/// not compared.
std::vector<std::string> outsideCalibration(const MissionKind& mission, const MissionKind& calibrated);

}  // namespace wattswath::calibration
