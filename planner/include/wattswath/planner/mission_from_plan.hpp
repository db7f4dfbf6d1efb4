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

/// A planned coverage flight as the mission mission/'s writers take, with notes for the user.
struct PlanMission {
  mission::PlannedMission mission;  ///< [deg], [m], [m/s] take-off, waypoints with speeds, geofence
  std::vector<std::string> notes;   ///< where the mission departs from the plan
};

/// The mission of `flown` planned for `problem` [m, local frame `frame`]: take-off to
/// problem.altitude [m] at problem.home, the end of every line or arc at that altitude flown at
/// that leg's cruise speed (at least 0.1 m/s), cruise and hover speed the fastest [m/s], and a
/// geofence of the area's holes and the no-fly zones that did not become holes. `home_altitude_amsl_m` [m] is home's height above mean sea level.
PlanMission missionFromPlan(const FlownPath& flown, const SurveyProblem& problem, const geometry::LocalFrame& frame,
                            double home_altitude_amsl_m);

}  // namespace wattswath::planner
