#pragma once
// `plan`'s finalists flown by the vehicle's autopilot model (planner/flight_score.hpp) with the
// same setup as `predict` (prediction_setup.hpp): the cheapest flight is the plan written, and
// the plan reports that flight's energy and time, which `predict` gives for the mission written.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "prediction_setup.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/flight_score.hpp"

namespace wattswath::apps {

/// One finalist as the autopilot flies it.
struct FlightRow {
  std::string label;             ///< "plan", "per-cell", "best spiral", "shortest path"
  double closed_form_j = 0.0;    ///< [J] the search's energy of the coverage route
  double energy_j = 0.0;         ///< [J] flown, take-off to landing
  double time_s = 0.0;           ///< [s] flown, take-off to landing
  double mission_energy_j = 0.0; ///< [J] the mission phase only
  double mission_time_s = 0.0;   ///< [s] the mission phase only
  double coverage_pct = 0.0;     ///< [%] coverage of the candidate
  bool baseline = false;         ///< flown for comparison only (the ground-station default), never written
};

/// The finalists flown and the choice.
struct PlanFlight {
  std::vector<FlightRow> rows;         ///< in the order scored
  std::size_t chosen = 0;              ///< index of the flight written
  std::string chosen_by_search;        ///< what the closed-form search chose ("plan" row's pattern)
  planner::PlanMission mission;        ///< the mission of the chosen flight
  bool arc_waypoints = false;          ///< its arcs written as waypoints along them (else chords)
  bool speeds_a_waypoint_early = false;  ///< its speed commands written a waypoint early (MissionOptions)
  double max_chord_offset_m = 0.0;     ///< [m] largest arc-to-chord distance of the chosen candidate's arcs
  mission::MissionPrediction prediction;  ///< its flight
  std::string autopilot;               ///< "ArduCopter 4.5 (arducopter-scurve model, ...)"
  mission::AutopilotConfig flown_by;   ///< the autopilot configuration that flew it
  /// A note when the chosen mission asks for flying the vehicle's calibration never saw
  /// (calibration::outsideCalibration, as `predict` says it), else nothing.
  std::optional<std::string> calibration_note;
};

/// `scoring` with the model, autopilot and settings of `setup` (its wind included: a run sets the
/// setup's wind to its own first), and the mission naming that autopilot (QGC's firmwareType).
/// `setup` must outlive the result (its model is referenced).
planner::FlightScoring withSetup(planner::FlightScoring scoring, const PredictionSetup& setup);

/// Flies the plan and its alternatives (per-cell plan, best spiral, shortest path) and makes
/// r.plan the cheapest flight among those covering at least the search's choice (less 0.1 %) (a note says so when
/// it is not the search's choice). `scoring` has everything but the model, autopilot and settings,
/// which come from the vehicle file at `vehicle_path` as `predict` sets them up.
PlanFlight flyFinalists(planner::PlanResult& r, planner::FlightScoring scoring, const std::string& vehicle_path,
                        std::vector<std::string>& notes);

/// The text lines of the flight.
void printFlight(const PlanFlight& f);

/// The JSON object of the flight ("flight" key of plan --json).
nlohmann::json flightJson(const PlanFlight& f);

}  // namespace wattswath::apps
