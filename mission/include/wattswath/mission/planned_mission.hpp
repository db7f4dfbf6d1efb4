#pragma once
/// @file planned_mission.hpp
/// Mission files written from a plan (`wattswath plan`): QGroundControl `.plan` (JSON), QGC WPL 110
/// `.waypoints` and a CSV of legs. Geodetic coordinates exist only here, at the output boundary; the
/// caller converts ENU metres with its frame. (Moved from planner/; a follow-up writes plans through
/// the item model of mission.hpp instead of this struct.)

#include <optional>
#include <string>
#include <vector>

#include "wattswath/geometry/frame.hpp"

namespace wattswath::mission {

/// A WGS84 position [deg]: geometry's geodetic point (its alt_m is not used by the writers).
using GeoPoint = geometry::GeoPoint;

/// One waypoint of a mission, flown towards at `speed_mps`.
struct PlannedWaypoint {
  GeoPoint position;        ///< [deg] where to fly
  double altitude_m = 0.0;  ///< [m] above home (MAV_FRAME_GLOBAL_RELATIVE_ALT)
  double speed_mps = 0.0;   ///< [m/s] ground speed on the leg that ends here (> 0)
  double hold_s = 0.0;      ///< [s] NAV_WAYPOINT param1: stop here and hold this long (0: fly through), >= 0
  std::optional<double> camera_trigger_m;  ///< [m] DO_SET_CAM_TRIGG_DIST written after this waypoint: photos
                                           ///< every this far from here on (0: photos stop), none when empty
  double acceptance_radius_m = 0.0;  ///< [m] NAV_WAYPOINT param2: how close PX4 must come (0: its NAV_ACC_RAD;
                                     ///< ArduCopter ignores it), >= 0
};

/// Autopilot family written into the `.plan` (QGroundControl's MAV_AUTOPILOT numbers).
enum class Firmware { ArduPilot = 3, PX4 = 12 };

/// MAV_TYPE of a multirotor with `rotor_count` rotors (3: 15 tricopter, 4: 2 quadrotor, 6: 13
/// hexarotor, 8: 14 octorotor); empty for any other count.
std::optional<int> mavTypeOfRotors(int rotor_count);

/// A complete mission: take-off at home, waypoints with speed changes, return to launch.
struct PlannedMission {
  GeoPoint home;                                ///< [deg] planned home / launch position
  double home_altitude_amsl_m = 0.0;            ///< [m] home altitude above mean sea level
  double takeoff_altitude_m = 10.0;             ///< [m] take-off height above home, (0, 1000]
  double cruise_speed_mps = 5.0;                ///< [m/s] QGC's time estimate speed, written as cruiseSpeed (rounded)
  double hover_speed_mps = 5.0;                 ///< [m/s] hoverSpeed of the .plan (rounded as cruiseSpeed)
  Firmware firmware = Firmware::ArduPilot;      ///< autopilot family (IRIS+ flights were ArduCopter)
  int vehicle_type = 2;                         ///< MAV_TYPE written as vehicleType: 2, 13, 14 or 15 (mavTypeOfRotors)
  /// true: the first DO_CHANGE_SPEED is written twice, for ArduCopter 4.1-4.4, which drops the first
  /// DO item after a take-off when it is a speed change (ArduPilot issue 21080, fixed in 4.5): the
  /// repeat runs after the first waypoint restarted the waypoint controller and is kept
  bool repeat_first_speed_change = false;
  std::vector<PlannedWaypoint> waypoints;       ///< in flight order (at least one)
  std::vector<std::vector<GeoPoint>> no_fly;    ///< [deg] exclusion polygons for the geofence
  std::vector<GeoPoint> fence_inclusion;        ///< [deg] inclusion polygon for the geofence (empty: none)
};

/// [m/s] The integer QGroundControl's and Mission Planner's cruiseSpeed / hoverSpeed get for
/// `speed_mps`: rounded to the nearest whole m/s, at least 1 (Mission Planner's .plan reader,
/// MissionFile.Mission, declares them int and Json.NET refuses 5.0 or 5.2 for an int).
int planSpeedField(double speed_mps);

/// Throws std::invalid_argument naming the field, index and value when `m` cannot be written
/// (no waypoints, latitude/longitude out of range, non-positive speeds or altitudes, a negative or
/// non-finite hold or trigger distance, a vehicle type that is not a multirotor's, a fence polygon
/// with fewer than 3 vertices).
void validate(const PlannedMission& m);

/// QGroundControl `.plan` JSON text (fileType "Plan", version 1; mission version 2 with SimpleItems:
/// 22 take-off, 178 DO_CHANGE_SPEED before each waypoint whose speed differs from the previous
/// waypoint's (written as given: planner::missionWaypoints decides the speeds), 16 waypoints (param1
/// the hold), 206 DO_SET_CAM_TRIGG_DIST after a waypoint with a camera command (param3 1: one photo
/// at once, as QGC's survey writes it), 20 return to launch; cruiseSpeed / hoverSpeed as integers
/// (planSpeedField); geoFence version 2 with the inclusion polygon and the no-fly zones as exclusion
/// polygons; rallyPoints version 2).
std::string toQgcPlan(const PlannedMission& m);

/// QGC WPL 110 text (tab separated; row 0 is home; same items as the `.plan`).
std::string toQgcWpl(const PlannedMission& m);

/// Checks `.plan` JSON text against the format QGroundControl loads (the keys, types and values
/// its JSON loader requires). Returns the problems found; empty means it loads.
std::vector<std::string> checkQgcPlan(const std::string& json_text);

/// Checks `.plan` JSON text against Mission Planner's reader (MissionFile.ReadFile: Json.NET into
/// the MissionFile classes, then ConvertToLocationwps): int fields must be JSON integers (no 5.0),
/// non-nullable fields not null, params 7 values, plannedHomePosition 3 numbers. Returns the
/// problems found; empty means it loads.
std::vector<std::string> checkMissionPlannerPlan(const std::string& json_text);

/// One flown leg for the CSV of legs (the GeoJSON path is written by geometry's coveragePathToGeoJson).
struct LegRecord {
  GeoPoint start;                ///< [deg] where the leg starts
  GeoPoint end;                  ///< [deg] where the leg ends
  std::string kind;              ///< "line", "arc" or "turn_in_place"
  std::string role;              ///< "sweep", "turn", "transit" or "climb"
  double length_m = 0.0;         ///< [m] distance flown
  double speed_start_mps = 0.0;  ///< [m/s] speed at the start
  double speed_cruise_mps = 0.0; ///< [m/s] cruise speed
  double speed_end_mps = 0.0;    ///< [m/s] speed at the end
  double time_s = 0.0;           ///< [s] duration
  double energy_j = 0.0;         ///< [J] electrical energy
};

/// CSV of legs with a header row (units in the column names); legs are numbered from 1, as the plan
/// report's table and map count them.
std::string toLegCsv(const std::vector<LegRecord>& legs);

}  // namespace wattswath::mission
