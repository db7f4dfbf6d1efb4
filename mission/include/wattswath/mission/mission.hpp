#pragma once
/// @file mission.hpp
/// What the autopilot is told: a mission as the items of a QGroundControl `.plan` or a QGC WPL 110
/// `.waypoints` file (MAVLink mission items), with the planned home. Geodetic here, as in the
/// files; flight.hpp turns it into local metres and a trajectory.

#include <cstdint>
#include <string>
#include <vector>

#include "wattswath/geometry/frame.hpp"

namespace wattswath::mission {

/// MAVLink MAV_CMD numbers this library knows (common.xml).
enum class Command : int {
  NavWaypoint = 16,          ///< fly to a position; param1 hold [s], param2 acceptance radius [m]
  NavLoiterUnlimited = 17,   ///< fly to a position and loiter there until the pilot ends it (the prediction ends on arrival)
  NavLoiterTurns = 18,       ///< circle a point; param1 turns, param3 radius [m] (< 0: counter-clockwise)
  NavLoiterTime = 19,        ///< fly to a position and hold there; param1 time [s]
  NavReturnToLaunch = 20,    ///< return home and land
  NavLand = 21,              ///< land at a position (0, 0: where the vehicle is)
  NavTakeoff = 22,           ///< climb to the item's altitude
  NavSplineWaypoint = 82,    ///< fly to a position on a spline; param1 hold [s]
  NavDelay = 93,             ///< wait; param1 delay [s]
  ConditionDelay = 112,      ///< delay the next DO command; param1 [s] (no effect on flight)
  ConditionDistance = 114,   ///< delay the next DO command until this close to the waypoint; param1 [m]
  ConditionYaw = 115,        ///< turn to a heading; param1 angle [deg], param2 rate [deg/s]
  DoJump = 177,              ///< jump to item param1, param2 times
  DoChangeSpeed = 178,       ///< param1 speed type (0/1 horizontal, 2 climb, 3 descent), param2 [m/s]
  DoSetHome = 179,           ///< set home (no effect on the trajectory here; listed)
  DoSetRelay = 181,          ///< relay (no effect on flight)
  DoSetServo = 183,          ///< servo (no effect on flight)
  DoSetRoi = 201,            ///< region of interest (no effect on the path)
  DoDigicamControl = 203,    ///< camera shot (no effect on flight)
  DoMountControl = 205,      ///< gimbal (no effect on flight)
  DoSetCamTriggDist = 206,   ///< camera trigger distance param1 [m] (0 stops)
  DoAuxFunction = 218,       ///< run an auxiliary switch function (assumed not to change the flight; noted)
  DoGimbalManagerPitchyaw = 1000,  ///< gimbal (no effect on flight)
  ImageStartCapture = 2000,  ///< camera (no effect on flight)
  ImageStopCapture = 2001,   ///< camera (no effect on flight)
  VideoStartCapture = 2500,  ///< camera (no effect on flight)
  VideoStopCapture = 2501,   ///< camera (no effect on flight)
  SetCameraMode = 530,       ///< camera (no effect on flight)
};

/// MAVLink MAV_FRAME of an item's altitude.
enum class AltitudeFrame : int {
  Absolute = 0,        ///< MAV_FRAME_GLOBAL: altitude above mean sea level [m]
  Mission = 2,         ///< MAV_FRAME_MISSION: the item has no position (DO commands)
  Relative = 3,        ///< MAV_FRAME_GLOBAL_RELATIVE_ALT: altitude above home [m]
  Terrain = 10,        ///< MAV_FRAME_GLOBAL_TERRAIN_ALT: above terrain (flat terrain at home assumed)
};

/// AltitudeFrame of a MAV_FRAME number as written: the _INT variants 5, 6, 11 (same meaning, integer
/// lat/lon on the wire) give 0, 3, 10. Throws std::invalid_argument for any other than 0, 2, 3, 5, 6, 10, 11.
AltitudeFrame altitudeFrame(int frame);

/// One mission item, as in the file (seq 0 of a `.waypoints` file is home and is not an item).
struct MissionItem {
  int seq = 0;                   ///< item number as the autopilot counts it (1 = first after home)
  int command = 0;               ///< MAV_CMD number (see Command)
  int frame = 3;                 ///< MAV_FRAME number as written in the file
  double param[4] = {0, 0, 0, 0};  ///< param1..param4 as written (NaN where the file has null/NaN)
  double lat_deg = 0.0;          ///< [deg] x / param5 / latitude as written (0 or NaN: no position)
  double lon_deg = 0.0;          ///< [deg] y / param6 / longitude as written
  double alt_m = 0.0;            ///< [m] z / param7 / altitude in `frame` as written
  bool autocontinue = true;      ///< false: the autopilot stops after this item
  std::string where;             ///< "FILE:LINE" or "FILE: mission.items[3]" for messages
};

/// True for DO_CHANGE_SPEED's param2 values that set no new speed: -1 (no change) and -2 (back to the
/// default speed), MAVLink's MAV_CMD_DO_CHANGE_SPEED sentinels [m/s].
inline bool isSpeedSentinel(double speed_mps) { return speed_mps == -1.0 || speed_mps == -2.0; }

/// A whole mission: the planned home and the items in order.
struct Mission {
  std::string source;                 ///< file the mission was read from
  std::string format;                 ///< "plan" or "waypoints"
  geometry::GeoPoint home;            ///< [deg, m AMSL] planned home (take-off point)
  bool home_known = false;            ///< false when the file gives no home (first position used)
  std::vector<MissionItem> items;     ///< in file order (home excluded)
  double plan_cruise_speed_mps = 0.0; ///< [m/s] `.plan` cruiseSpeed (0 when absent; QGC estimate only)
  double plan_hover_speed_mps = 0.0;  ///< [m/s] `.plan` hoverSpeed (0 when absent; QGC estimate only)
  int firmware_type = 0;              ///< `.plan` firmwareType (MAV_AUTOPILOT: 3 ArduPilot, 12 PX4; 0 unknown)
  int vehicle_type = 0;               ///< `.plan` vehicleType (MAV_TYPE: 2 quad, 13 hexa, ...; 0 unknown)
  std::vector<std::string> warnings;  ///< what was accepted leniently or ignored, each naming its item
};

/// Name of a MAV_CMD number ("NAV_WAYPOINT", ...), or "MAV_CMD <n>" when unknown.
std::string commandName(int command);

/// True for the commands that move the vehicle (NAV_*) as opposed to DO_* / CONDITION_*.
bool isNavCommand(int command);

/// True for the commands the readers accept: NAV_TAKEOFF, NAV_WAYPOINT, NAV_SPLINE_WAYPOINT,
/// NAV_LOITER_TIME, NAV_LOITER_TURNS, NAV_RETURN_TO_LAUNCH, NAV_LAND, NAV_DELAY, DO_CHANGE_SPEED,
/// DO_SET_CAM_TRIGG_DIST, DO_JUMP, CONDITION_YAW, CONDITION_DELAY, and the commands that do not
/// move the vehicle: camera, video, gimbal, mount, servo, relay and ROI commands (with their repeat,
/// configure and ROI-variant forms), CONDITION_DISTANCE, DO_FENCE_ENABLE and the DO_LAND_START
/// marker (docs/missions.md). Not: the loiter without end (17), DO_SET_HOME (moves the return
/// point), payload commands that change the mass (DO_GRIPPER, DO_SPRAYER), mode changes, VTOL
/// commands or any other.
bool isSupportedCommand(int command);

/// True for the commands flown to a position given by lat/lon/alt (NAV_TAKEOFF, NAV_WAYPOINT,
/// NAV_SPLINE_WAYPOINT, NAV_LOITER_TIME, NAV_LOITER_TURNS, NAV_LAND); their frame must be a global
/// one (0, 3, 10, 5, 6, 11).
bool isPositional(int command);

/// True when `item` is positional and gives a position: lat/lon finite and not both 0 (ArduPilot
/// flies lat = lon = 0 as "where the vehicle is", e.g. a take-off or land in place).
bool hasPosition(const MissionItem& item);

/// Same seq, command, frame, params, position and autocontinue; NaN equals NaN; `where` is not compared.
bool operator==(const MissionItem& a, const MissionItem& b);
/// Negation of ==.
bool operator!=(const MissionItem& a, const MissionItem& b);

/// Same home (and home_known), items, plan speeds, firmware and vehicle type; source, format and
/// warnings are not compared.
bool operator==(const Mission& a, const Mission& b);
/// Negation of ==.
bool operator!=(const Mission& a, const Mission& b);

}  // namespace wattswath::mission
