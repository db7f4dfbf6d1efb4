#pragma once
/// @file mission_from_plan.hpp
/// The mission the autopilot is told for a planned coverage flight: which waypoints, speed
/// commands, holds, camera commands and fences go into the `.plan` / `.waypoints` that mission/'s
/// writers write. The one place where the planner's speeds become speed commands and its stops
/// become holds (the command line only writes the result).

#include <optional>
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

/// [m] Largest distance between a planned arc and the straight legs the mission flies instead when
/// arcs are written as waypoints (MissionOptions::arc_waypoints): as many as keep every chord within this of the arc
/// (ArduCopter and PX4 fly straight legs between waypoints; a chord of a whole 90 degree arc of
/// 15 m radius would pass 4.4 m inside it).
inline constexpr double kArcChordSagitta = 0.5;

/// [m/s] A waypoint gets a new speed command (DO_CHANGE_SPEED) only when its leg's speed differs
/// from the speed in force by more than this; smaller changes keep the speed in force.
inline constexpr double kSpeedChangeTolerance = 0.05;

/// [m/s] Lowest speed ever commanded. ArduCopter ignores DO_CHANGE_SPEED below WPNAV_WP_SPEED_MIN
/// (AC_WPNav::set_speed_xy keeps the speed in force): 100 cm/s in 3.x, 20 cm/s in 4.x (lower in the
/// newest releases). A leg planned slower (the speed optimiser's 0.05 m/s floor on legs that brake
/// as deep as they can) is commanded at this speed, which every ArduCopter obeys, and a note says so.
inline constexpr double kMinCommandedSpeed = 1.0;

/// [s] Hold written at every planned stop (NAV_WAYPOINT param1). ArduCopter flies through a
/// waypoint without a hold, blending it into the next leg (../shared/data/sitl: no stop at any plain
/// waypoint), and keeps the hold in whole seconds, so 1 s is the least that makes it stop there.
inline constexpr double kStopHoldSeconds = 1.0;

/// [m] Acceptance radius written into every waypoint of a PX4 mission (NAV_WAYPOINT param2). PX4
/// switches to the next waypoint as soon as the vehicle is within it (NAV_ACC_RAD, 10 m by default,
/// when the item gives none) and turns towards the next from there, so with its default a survey's
/// sweep lines would end up to 9 m short of the area's edge (measured on the bundled example:
/// median 6 m). 2 m cuts corners as deep as ArduCopter's WPNAV_RADIUS default, which the planner's
/// margins are built for; ArduCopter ignores the field.
inline constexpr double kPx4AcceptanceRadius = 2.0;

/// [m/s] A leg whose planned end speed is below this ends in a stop (a sharp corner, a turn in place).
inline constexpr double kStopSpeed = 1e-6;

/// What the mission carries beyond its waypoints and speeds.
struct MissionOptions {
  double trigger_distance_m = 0.0;        ///< [m] camera trigger distance on sweeps (0: no camera commands), >= 0
  double stop_hold_s = kStopHoldSeconds;  ///< [s] hold at each planned stop (0: none), >= 0
  int rotor_count = 4;                    ///< [-] the vehicle's rotors, for the .plan's vehicleType
  mission::Firmware firmware = mission::Firmware::ArduPilot;  ///< the autopilot named in the .plan (firmwareType)
  /// true: the first speed change written twice (PlannedMission::repeat_first_speed_change), for
  /// ArduCopter 4.1-4.4
  bool repeat_first_speed_change = false;
  double fence_margin_m = 0.0;            ///< [m] inclusion fence keeping every flown point this far inside it
                                          ///< (0: no inclusion fence), >= 0
  bool arc_waypoints = false;             ///< true: arcs written as waypoints along them (kArcChordSagitta);
                                          ///< false: an arc is one waypoint at its end, flown by the autopilot's
                                          ///< own cornering along the chord
  double no_fly_margin_m = 0.0;           ///< [m] margin the straight legs between waypoints are checked
                                          ///< against (0: not checked), >= 0
  /// true: each leg's speed command is the faster of its own planned speed and the next leg's, for
  /// ArduCopter, which flies a speed command late: before 4.1 an increase only from the next waypoint
  /// on (the leg's leash is computed before the new speed reaches the position controller), from 4.1
  /// on the leg after a waypoint flown through is planned before its command runs and re-planned in
  /// flight, a second acceleration after the first (docs/autopilots.md)
  bool speeds_a_waypoint_early = false;
};

/// One waypoint of the mission in the local ENU frame, before conversion to WGS84.
struct MissionWaypoint {
  geometry::Point position = geometry::Point::Zero();  ///< [m] ENU end of the leg flown into it
  double speed_mps = 0.0;          ///< [m/s] commanded ground speed on the leg into it (>= kMinCommandedSpeed)
  double planned_speed_mps = 0.0;  ///< [m/s] the planner's cruise speed of that leg
  int leg = -1;                    ///< [-] index in the flown path's legs of the leg ending here (-1: a start)
  double hold_s = 0.0;             ///< [s] hold here: MissionOptions::stop_hold_s at a planned stop, else 0
  std::optional<double> camera_trigger_m;  ///< [m] camera command after this waypoint (0: photos stop)
};

/// The waypoints, speed commands, holds and camera commands of a flown path, with notes.
struct MissionWaypoints {
  std::vector<MissionWaypoint> waypoints;  ///< [m], [m/s] in flight order
  std::vector<std::string> notes;          ///< sentences for the user (e.g. speeds raised to the floor)
  int holds = 0;                           ///< [-] waypoints with a hold (planned stops)
  int camera_runs = 0;                     ///< [-] stretches of sweep flown with the camera on
  int photos = 0;                          ///< [-] photos the camera commands take (photosAlong per run)
  double camera_length_m = 0.0;            ///< [m] length flown with the camera on
  std::vector<int> camera_legs;            ///< [-] indices of the flown legs the camera is on along
};

/// Waypoints [m] and speed commands [m/s] of `flown`: the end of every line or arc (turns in place
/// add none) at that leg's cruise speed, ends within kMinWaypointSpacing of the last waypoint
/// merged into it, speeds held within kSpeedChangeTolerance and raised to kMinCommandedSpeed. A
/// waypoint where the plan stops gets options.stop_hold_s (not the last one: the return follows).
/// With a trigger distance, each run of sweep legs gets the camera on at the waypoint where it
/// starts and off (0) at the waypoint where it ends, as QGC's survey does; transits and turns take
/// no photos.
MissionWaypoints missionWaypoints(const FlownPath& flown, const MissionOptions& options = {});

/// A planned coverage flight as the mission mission/'s writers take, with notes for the user.
struct PlanMission {
  mission::PlannedMission mission;  ///< [deg], [m], [m/s] take-off, waypoints with speeds, geofence
  std::vector<std::string> notes;   ///< where the mission departs from the plan (from missionWaypoints)
  int holds = 0;                    ///< [-] waypoints with a hold
  int camera_runs = 0;              ///< [-] sweeps flown with the camera on
  int photos = 0;                   ///< [-] photos the mission's camera commands take
  double camera_length_m = 0.0;     ///< [m] length flown with the camera on
  std::vector<int> camera_legs;     ///< [-] indices of the flown legs the camera is on along
  double fence_distance_m = 0.0;    ///< [m] how far the inclusion fence lies outside the area (0: none)
  int legs_within_margin = 0;       ///< [-] straight legs between waypoints (arcs written as chords) that
                                    ///< come within options.no_fly_margin_m of a no-fly zone (each noted)
};

/// The mission of `flown` planned for `problem` [m, local frame `frame`]: take-off to
/// problem.altitude [m] at problem.home, missionWaypoints at that altitude, cruise and hover speed
/// the fastest command [m/s], the vehicle type of options.rotor_count, and a geofence of the area's
/// holes and the no-fly zones that did not become holes, with the inclusionFence (margin.hpp) when
/// options.fence_margin_m > 0. With options.no_fly_margin_m > 0 the straight legs between the
/// waypoints (what the autopilot flies; an arc is written as its chord) are checked against the
/// no-fly zones and each one within the margin is noted. `home_altitude_amsl_m` [m] is home's
/// height above mean sea level.
PlanMission missionFromPlan(const FlownPath& flown, const SurveyProblem& problem, const geometry::LocalFrame& frame,
                            double home_altitude_amsl_m, const MissionOptions& options = {});

}  // namespace wattswath::planner
