#pragma once
/// @file mission_from_plan.hpp
/// The mission the autopilot is told for a planned coverage flight: which waypoints and which
/// speed commands go into the `.plan` / `.waypoints` that mission/'s writers write. The one place
/// where the planner's speeds become speed commands (the command line only writes the result).

#include <string>
#include <vector>

#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/planned_mission.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/speed.hpp"

namespace wattswath::planner {

/// [m] Shortest distance between consecutive waypoints: a leg ending closer than this to the last
/// written waypoint (the 1 mm joins between arcs, tiny arcs) is merged into that waypoint instead of
/// becoming one, so no waypoint pair is degenerate; every leg end stays within this of a waypoint.
inline constexpr double kMinWaypointSpacing = 0.5;

/// [m/s] A waypoint gets a new speed command (DO_CHANGE_SPEED) only when its leg's speed differs
/// from the speed in force by more than this; smaller changes keep the speed in force.
inline constexpr double kSpeedChangeTolerance = 0.05;

/// [m/s] Lowest speed ever commanded. ArduCopter ignores DO_CHANGE_SPEED below WPNAV_WP_SPEED_MIN
/// (AC_WPNav::set_speed_xy keeps the speed in force): 100 cm/s in 3.x, 20 cm/s in 4.x (lower in the
/// newest releases). A leg planned slower (the speed optimiser's 0.05 m/s floor on legs that brake
/// as deep as they can) is commanded at this speed, which every ArduCopter obeys, and a note says so.
inline constexpr double kMinCommandedSpeed = 1.0;

/// One waypoint of the mission in the local ENU frame, before conversion to WGS84.
struct MissionWaypoint {
  geometry::Point position = geometry::Point::Zero();  ///< [m] ENU end of the leg flown into it
  double speed_mps = 0.0;          ///< [m/s] commanded ground speed on the leg into it (>= kMinCommandedSpeed)
  double planned_speed_mps = 0.0;  ///< [m/s] the planner's cruise speed of that leg
  int leg = -1;                    ///< [-] index in the flown path's legs of the leg ending here
};

/// The waypoints and speed commands of a flown path, with notes where they depart from the plan.
struct MissionWaypoints {
  std::vector<MissionWaypoint> waypoints;  ///< [m], [m/s] in flight order
  std::vector<std::string> notes;          ///< sentences for the user (e.g. speeds raised to the floor)
};

/// Waypoints [m] and speed commands [m/s] of `flown`: the end of every line or arc (turns in place
/// add none) at that leg's cruise speed, ends within kMinWaypointSpacing of the last waypoint
/// merged into it, speeds held within kSpeedChangeTolerance and raised to kMinCommandedSpeed.
MissionWaypoints missionWaypoints(const FlownPath& flown);

/// A planned coverage flight as the mission mission/'s writers take, with notes for the user.
struct PlanMission {
  mission::PlannedMission mission;  ///< [deg], [m], [m/s] take-off, waypoints with speeds, geofence
  std::vector<std::string> notes;   ///< where the mission departs from the plan (from missionWaypoints)
};

/// The mission of `flown` planned for `problem` [m, local frame `frame`]: take-off to
/// problem.altitude [m] at problem.home, missionWaypoints at that altitude, cruise and hover speed
/// the fastest command [m/s], and a geofence of the area's holes and the no-fly zones that did not
/// become holes. `home_altitude_amsl_m` [m] is home's height above mean sea level.
PlanMission missionFromPlan(const FlownPath& flown, const SurveyProblem& problem, const geometry::LocalFrame& frame,
                            double home_altitude_amsl_m);

}  // namespace wattswath::planner
