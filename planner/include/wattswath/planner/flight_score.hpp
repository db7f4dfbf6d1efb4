#pragma once
/// @file flight_score.hpp
/// One flight model for planning and prediction: the planner's finalists written as the missions
/// the autopilot is told (missionFromPlan, then the `.plan` text `predict` would read) and flown
/// by the vehicle's autopilot model (mission/predict.hpp), so the plan's reported energy and time
/// are what `wattswath predict` gives for the mission it writes, and the finalist the autopilot
/// flies cheapest is the one chosen. The search itself keeps the fast closed forms.

#include <string>
#include <vector>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/predict.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/mission_from_plan.hpp"

namespace wattswath::planner {

/// What the flight model needs besides the candidate.
struct FlightScoring {
  const SurveyProblem* problem = nullptr;            ///< the problem the candidates cover
  const geometry::LocalFrame* frame = nullptr;       ///< the area's local frame
  double home_altitude_amsl_m = 0.0;                 ///< [m] home above mean sea level
  MissionOptions mission;                            ///< how missions are written
  const energy::Vehicle* vehicle = nullptr;          ///< the vehicle
  const energy::EnergyModel* model = nullptr;        ///< the energy model predict uses
  mission::AutopilotConfig autopilot;                ///< the vehicle's autopilot
  mission::PredictSettings settings;                 ///< as predict sets them (calibrated behaviour)
  int threads = 2;                                   ///< flights simulated at once (>= 1; the results do not depend on it)
  /// Candidates flown only as a ground station writes them (baselines): never with their speed
  /// commands a waypoint early.
  std::vector<const PlanCandidate*> as_written;
};

/// One candidate flown by the autopilot model.
struct FlightScore {
  std::string label;                      ///< "plan", "per-cell", "shortest path", "best spiral", ...
  const PlanCandidate* candidate = nullptr;  ///< the candidate scored (not owned)
  bool arc_waypoints = false;             ///< how its arcs are written (MissionOptions::arc_waypoints)
  bool speeds_a_waypoint_early = false;   ///< its speed commands (MissionOptions::speeds_a_waypoint_early)
  double closed_form_energy_j = 0.0;      ///< [J] the search's closed-form energy of the coverage route
  PlanMission mission;                    ///< the mission written for it
  mission::MissionPrediction prediction;  ///< its flight, take-off to landing
};

/// Sets the autopilot that flies the missions and the mission dialect it reads
/// (FlightScoring::mission.firmware: PX4, else ArduPilot), which go together.
void setAutopilot(FlightScoring& scoring, const mission::AutopilotConfig& autopilot);

/// `written` flown by the autopilot model exactly as `predict` flies the `.plan` text of it
/// (`source` names that text in errors).
mission::MissionPrediction flyWrittenMission(const PlanMission& written, const FlightScoring& scoring, const std::string& source);

/// Flies each labelled candidate's mission (in order); a candidate with arcs twice: its arcs as
/// chords flown by the autopilot's own cornering (unless a chord comes within the no-fly margin)
/// and as waypoints along them (MissionOptions::arc_waypoints). For ArduCopter (both families,
/// which fly a speed command late) each of those also with its speed commands a waypoint early
/// (MissionOptions::speeds_a_waypoint_early), unless it is in FlightScoring::as_written. Missions with the same .plan text
/// are flown once; the flights run on FlightScoring::threads threads. Throws what missionFromPlan,
/// parseQgcPlan and predictMission throw (for the first such mission in order).
std::vector<FlightScore> scoreByFlight(const std::vector<std::pair<std::string, const PlanCandidate*>>& candidates,
                                       const FlightScoring& scoring);

/// Index of the cheapest flight among those whose coverage is at least the first's (the search's
/// choice) less `coverage_slack_pct` [%], so a cheaper flight never buys its saving with coverage.
std::size_t cheapestFlight(const std::vector<FlightScore>& scores, double coverage_slack_pct = 0.1);

}  // namespace wattswath::planner
