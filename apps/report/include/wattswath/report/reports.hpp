#pragma once
/// @file reports.hpp
/// The wattswath reports as plain data structs and functions that turn them into self-contained
/// HTML pages. Commands fill the structs from library results; nothing here computes physics
/// (binned residual statistics and unit scaling are display only).

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "wattswath/energy/model.hpp"
#include "wattswath/geometry/polygon.hpp"
#include "wattswath/report/html.hpp"

namespace wattswath::report {

/// Free-form key/value lines shown at the top of a report (inputs, settings, totals).
using Facts = std::vector<std::pair<std::string, std::string>>;

// ---------------------------------------------------------------- plan report

/// One mission item as drawn: its number on the map and its reached time on the time axis.
struct MissionMark {
  int seq = -1;                             ///< the item's number in the mission file (-1: added by the autopilot model)
  std::string command;                      ///< MAVLink command name, e.g. "NAV_WAYPOINT"
  std::optional<geometry::Point> position;  ///< [m] ENU target from home (none: no position, e.g. land in place)
  double reached_s = 0.0;                   ///< [s] since the take-off command when reached (NaN: never)
  double energy_j = 0.0;                    ///< [J] energy while the item was active
  double time_s = 0.0;                      ///< [s] time while the item was active
  double distance_m = 0.0;                  ///< [m] distance flown while the item was active
};

/// One leg of the chosen plan, as drawn on the map.
struct PlanLeg {
  std::vector<geometry::Point> points;  ///< [m] local ENU polyline (arcs sampled; >= 2 points, or 1 for a turn in place)
  std::string role;                     ///< "sweep", "turn", "transit", "climb"
  double speed = 0.0;                   ///< [m/s] cruise speed of the leg
  double energy = 0.0;                  ///< [J] energy of the leg
  double time = 0.0;                    ///< [s] duration of the leg
  double length = 0.0;                  ///< [m] length flown
};

/// One candidate plan scored by the planner.
struct PlanCandidate {
  std::string pattern;       ///< "boustrophedon", "spiral", ...
  double sweep_angle = 0.0;  ///< [rad] sweep direction (0 = lines along east); ignored for patterns without one
  double energy = 0.0;       ///< [J] total energy of the candidate
  bool chosen = false;       ///< the plan the planner kept
};

/// How one cell of the plan is covered (per-cell search).
struct PlanCell {
  std::string pattern;       ///< "boustrophedon" or "spiral"
  double sweep_angle = 0.0;  ///< [rad] sweep direction of a boustrophedon cell
  double energy = 0.0;       ///< [J] the cell's route flown alone, rest to rest
  double area = 0.0;         ///< [m^2] cell area
};

/// A reference plan to compare against (shortest path, ground-station default, ...).
struct PlanBaseline {
  std::string name;     ///< e.g. "shortest path", "ground-station default"
  double energy = 0.0;  ///< [J] total energy
  double length = 0.0;  ///< [m] path length (0 = unknown)
  double time = 0.0;    ///< [s] flight time (0 = unknown)
};

/// Battery state over the mission (e.g. Hwang et al.'s Peukert battery with linear voltage drop).
struct BatteryTrace {
  std::vector<double> t;        ///< [s] time since take-off
  std::vector<double> soc;      ///< [%] usable charge left as the autopilot counts it (100 full, 0 at the cut-off)
  std::vector<double> voltage;  ///< [V] terminal voltage (may be empty)
  std::string model;            ///< which battery model, e.g. "Hwang et al. Eq. 19-21"
  double reserve_pct = std::numeric_limits<double>::quiet_NaN();  ///< [%] usable charge to keep on landing (NaN: none drawn)
  std::optional<double> cutoff_s;  ///< [s] when the battery reaches its cut-off in flight (none: it does not)
};

/// One sortie (one battery's flight) of a plan split for the battery, as drawn and tabled.
struct PlanSortie {
  std::string name;                    ///< e.g. "sortie 1" or "vehicle 2, sortie 1"
  std::string file;                    ///< its mission file, e.g. "sortie_01.plan"
  std::vector<geometry::Point> track;  ///< [m] local ENU, the flight as the autopilot model flies it
  double energy_j = 0.0;               ///< [J] take-off command to landing
  double time_s = 0.0;                 ///< [s] take-off command to landing
  double soc_landing_pct = 0.0;        ///< [%] usable charge left on landing
  int photos = -1;                     ///< [-] photos taken (-1: no camera)
  int vehicle = 0;                     ///< [-] the fleet vehicle flying it, 1.. (0: no fleet)
  double start_s = 0.0;                ///< [s] take-off command after the fleet's first (fleet only)
  double delay_s = 0.0;                ///< [s] of its start that keeps the separation (fleet only)
};

/// The plan split into sorties, and (optionally) shared among a fleet flying at once.
struct PlanSorties {
  std::vector<PlanSortie> sorties;  ///< in flight order (fleet: by vehicle, then order)
  double single_energy_j = 0.0;     ///< [J] the idealised one flight with an unlimited battery
  double single_time_s = 0.0;       ///< [s] the same flight's time
  std::string single_base;          ///< what that flight is, e.g. "mission.plan flown by arducopter-4 in one flight"
  double reserve_pct = 25.0;        ///< [%] usable charge each sortie keeps on landing
  int vehicles = 0;                 ///< [-] fleet size (0: no fleet)
  double makespan_s = 0.0;          ///< [s] first take-off command to the last landing (fleet)
  double swap_time_s = 0.0;         ///< [s] on the ground between two sorties of a vehicle (fleet)
  double launch_interval_s = 0.0;   ///< [s] between the vehicles' first take-offs (fleet)
  double separation_m = 0.0;        ///< [m] horizontal distance kept between airborne vehicles (fleet)
  double min_separation_m = 0.0;    ///< [m] smallest found on the flown trajectories (fleet; inf: never two airborne)
};

/// What to colour the map path by.
enum class PlanColour { Speed, Power };

/// Everything the plan report shows. Fill what you have; empty parts are left out with a note.
struct PlanReportData {
  std::string title = "wattswath plan";              ///< page title
  Facts facts;                                       ///< vehicle, area, settings, totals
  std::vector<geometry::PolygonWithHoles> areas;     ///< survey areas with holes [m]
  std::vector<geometry::Ring> no_fly;                ///< no-fly zones [m]
  std::optional<geometry::Point> home;               ///< [m] take-off / landing point
  std::vector<PlanLeg> legs;                         ///< the chosen path in flight order
  PlanColour colour_by = PlanColour::Speed;          ///< map colour (power = leg energy / leg time)
  energy::Breakdown coverage;                        ///< energy of the coverage legs by effect and phase (Table III rows)
  energy::Breakdown transit;                         ///< energy of the transits (empty effects = none)
  std::vector<PlanCandidate> candidates;             ///< scored candidates (energy vs sweep angle); the chosen one is a marker
  std::vector<PlanCell> cells;                       ///< per-cell choices of the plan, in flight order (may be empty)
  std::vector<PlanBaseline> baselines;               ///< baselines drawn as horizontal lines
  std::optional<BatteryTrace> battery;               ///< battery over the mission, when known
  std::vector<MissionMark> items;                    ///< the mission's items, numbered as in the mission file (map labels)
  std::optional<PlanSorties> sorties;                ///< the split for the battery (plan --sorties), when asked
};

/// Builds the plan report (map, Table III-style breakdown + bar chart, candidates, battery).
HtmlReport planReport(const PlanReportData& data);
/// Appends the sorties section to `report`: a map with each sortie in its own colour and dash
/// pattern (legend), a table per sortie, the total against the one unlimited-battery flight, and
/// the fleet's schedule when there is one.
void addPlanSorties(HtmlReport& report, const PlanReportData& data);

// ---------------------------------------------------------------- validation report

/// A span of one phase of flight in a log.
struct PhaseSpan {
  double t0 = 0.0;    ///< [s] start
  double t1 = 0.0;    ///< [s] end
  std::string phase;  ///< phase name ("accelerate", "cruise", "brake", "turn", "climb", "hover", ...)
  std::size_t log = 0;  ///< which log of ValidationReportData::log_names the span belongs to
};

/// Measured against modelled energy of one leg (or phase) of a log.
struct LegEnergyPair {
  std::string label;     ///< e.g. "leg 3" (hover tooltip)
  double measured = 0.0;  ///< [J]
  double modelled = 0.0;  ///< [J]
};

/// One step of the error staircase (model as given, refitted, + each added effect).
struct ErrorStep {
  std::string label;    ///< e.g. "vehicle physics", "+ parasitic_drag"
  double error = 0.0;   ///< [ValidationReportData::error_unit] held-out error after this step
  std::string group{};  ///< the logs the error is computed on, e.g. "training logs" (coloured, with a legend; "" = one colour)
};

/// One row of the diagnosis table.
struct DiagnosisRow {
  std::string effect;                 ///< candidate effect name
  double improvement_pct = 0.0;       ///< [%] held-out error reduction when added
  std::string fitted;                 ///< fitted values with uncertainty and units, e.g. "C_D A = 0.019 +- 0.002 m^2"
  std::string meaning;                ///< physical reading, e.g. "wind 4 m/s from 120 deg"
  bool accepted = false;              ///< the diagnosis keeps it
};

/// The residual of a diagnosed model against one signal that carries it (issue 18), binned.
struct SignalCurve {
  std::string signal;            ///< e.g. "power_rate"
  std::string unit;              ///< unit of the signal, e.g. "W/s"
  std::string sentence;          ///< what kinds of effect leave this signature
  std::vector<double> x;         ///< bin centres, in `unit`
  std::vector<double> residual;  ///< [W] mean measured - modelled power in each bin
  std::string label;             ///< what the signal is, for the axis and caption ("" = `signal`)
};

/// Everything the validation report shows: one or more logs, their samples one after the other
/// (each log in time order); residual plots pool all logs, power over time is one figure per log.
struct ValidationReportData {
  std::string title = "wattswath model validation";  ///< page title
  Facts facts;                                       ///< log, vehicle, model, totals
  std::vector<std::string> log_names;                ///< name of each log (empty: one unnamed log)
  std::vector<std::size_t> log_start;                ///< index of each log's first sample (empty: one log from 0)
  std::vector<double> t;                             ///< [s] sample times
  std::vector<double> measured_power;                ///< [W] per sample
  std::vector<double> modelled_power;                ///< [W] per sample
  std::vector<double> speed;                         ///< [m/s] horizontal ground speed per sample (may be empty)
  std::vector<double> climb_rate;                    ///< [m/s] vertical speed per sample (may be empty)
  std::vector<double> heading;                       ///< [rad] ENU track heading per sample (may be empty)
  std::vector<PhaseSpan> phases;                     ///< shaded on the power plot
  std::vector<LegEnergyPair> legs;                   ///< leg energies, measured vs modelled
  std::vector<ErrorStep> staircase;                  ///< error before/after each added effect
  std::string error_label = "held-out RMSE";         ///< what the staircase error is
  std::string error_unit = "W";                      ///< unit of the staircase error
  std::string staircase_title = "Error as effects are added";  ///< the staircase figure's title
  std::string staircase_caption = "Each bar is the model after one more step; lower is better.";  ///< and its caption
  std::vector<DiagnosisRow> diagnosis;               ///< candidate effects, best first
  std::string diagnosis_caption = "Candidate effects, best first";  ///< caption of the diagnosis table
  int residual_bins = 12;                            ///< [-] bins of the residual plots, 2..100
  std::string verdict;                               ///< the diagnosis's verdict in words (empty: none)
  std::vector<SignalCurve> signal_curves;            ///< residual against the signals carrying it
};

/// Builds the validation report (power over time, residuals, leg energies, staircase, diagnosis).
/// Throws std::invalid_argument when per-sample vectors differ in length.
HtmlReport validationReport(const ValidationReportData& data);
/// Appends the validation report's sections (all but its title and facts) to `report`; throws
/// like validationReport.
void addValidation(HtmlReport& report, const ValidationReportData& data);

// ---------------------------------------------------------------- turn-strategy and speed reports

/// One row of the turn-strategy comparison (Marins et al. Table V).
struct TurnRow {
  double beta = 0.0;            ///< [rad] interior angle between the branches
  double leg_length = 0.0;      ///< [m] length of each branch
  double sharp_energy = 0.0;    ///< [J] stop, turn in place, go (Eq. 12)
  double rounded_energy = 0.0;  ///< [J] constant speed on the rounded path (Eq. 16)
  double sharp_speed = 0.0;     ///< [m/s] cruise speed of the sharp stop
  double rounded_speed = 0.0;   ///< [m/s] speed of the rounded path
  std::optional<double> paper_saving_pct;  ///< [%] the paper's saving for this row, when it has one
};

/// Everything the turn-strategy report shows.
struct TurnReportData {
  std::string title = "wattswath turn strategies";  ///< page title
  Facts facts;                                      ///< vehicle, limits, settings
  std::vector<TurnRow> rows;                        ///< grouped by angle in the plots
  std::optional<double> focus_beta;                 ///< [rad] the user's corner angle, drawn alone when angles overlap
  double overlap_tolerance = 0.05;                  ///< [-] relative spread across angles below which one angle is drawn
};

/// Builds the turn-strategy report (energy vs leg length per angle, saving, Table V).
HtmlReport turnReport(const TurnReportData& data);

/// Optimal cruise speed against leg length for one model variant (Marins et al. Fig. 3).
struct SpeedCurve {
  std::string name;              ///< e.g. "full model", "no drag", "no kinetic"
  std::vector<double> distance;  ///< [m] leg lengths
  std::vector<double> speed;     ///< [m/s] optimal cruise speed per length
};

/// Energy of one leg against its cruise speed, with the optimum.
struct LegEnergyCurve {
  double distance = 0.0;       ///< [m] leg length
  std::vector<double> speed;   ///< [m/s] cruise speeds
  std::vector<double> energy;  ///< [J] leg energy per speed
  double best_speed = 0.0;     ///< [m/s] optimum
  double best_energy = 0.0;    ///< [J] energy at the optimum
};

/// Everything the optimal-speed report shows.
struct SpeedReportData {
  std::string title = "wattswath optimal cruise speed";  ///< page title
  Facts facts;                                           ///< vehicle, limits
  std::vector<SpeedCurve> curves;                        ///< v_opt vs distance per model variant
  std::vector<LegEnergyCurve> legs;                      ///< E(v) for a few leg lengths
  std::optional<double> v_max;                           ///< [m/s] speed limit (drawn as a line)
  std::string leg_ends = "stop-to-stop";                 ///< how the legs begin and end, for the captions
};

/// Builds the optimal-speed report (v_opt vs distance, leg energy vs speed).
HtmlReport speedReport(const SpeedReportData& data);

// ---------------------------------------------------------------- mission report (predict)

/// Time, energy and distance of one flight phase (or of the whole flight).
struct MissionPhaseTotals {
  std::string phase;        ///< "takeoff", "mission", "return", "landing" (or "total")
  double time_s = 0.0;      ///< [s] duration
  double energy_j = 0.0;    ///< [J] electrical energy
  double distance_m = 0.0;  ///< [m] distance flown (3-D)
};

/// Everything the mission report (`predict --report`) shows: the predicted trajectory sample by
/// sample, the items, the phase totals and the battery.
struct MissionReportData {
  std::string title = "wattswath mission prediction";  ///< page title
  Facts facts;                                        ///< mission, vehicle, autopilot, totals
  std::vector<double> t;                              ///< [s] sample times since the take-off command
  std::vector<double> x;                              ///< [m] east of home per sample
  std::vector<double> y;                              ///< [m] north of home per sample
  std::vector<double> z;                              ///< [m] height above home per sample
  std::vector<double> speed;                          ///< [m/s] speed along the path (3-D) per sample
  std::vector<std::string> phase;                     ///< flight phase per sample: "takeoff", "mission", "return", "landing"
  std::vector<MissionMark> items;                     ///< mission items in flight order
  std::vector<MissionPhaseTotals> phases;             ///< per phase, in flight order
  MissionPhaseTotals total;                           ///< take-off command to landing
  std::optional<BatteryTrace> battery;                ///< usable charge left [%] in BatteryTrace::soc, when the vehicle has a battery
  double reserve_pct = 25.0;                          ///< [%] usable charge to keep on landing (the reserve line)
  std::string verdict;                                ///< one plain sentence on the reserve
};

/// Builds the mission report (map by phase with waypoint numbers, speed / altitude / battery over
/// time, phase table and verdict). Throws std::invalid_argument when per-sample vectors differ in length.
HtmlReport missionReport(const MissionReportData& data);

// ---------------------------------------------------------------- mission replay (replay --mission)

/// One leg between consecutive waypoints of a logged mission, measured and predicted (NaN: unmatched).
struct LegComparison {
  std::string label;       ///< the waypoint numbers, e.g. "3-4"
  double measured_s = 0.0;   ///< [s] leg time in the log
  double predicted_s = 0.0;  ///< [s] leg time predicted
  double measured_j = 0.0;   ///< [J] leg energy in the log
  double predicted_j = 0.0;  ///< [J] leg energy predicted
};

/// A logged flight of a known mission against the mission's prediction.
struct MissionReplayFlight {
  std::string name;                          ///< the log
  std::string mission;                       ///< the mission file
  std::vector<double> measured_t;            ///< [s] log samples since the take-off command
  std::vector<double> measured_speed;        ///< [m/s] logged speed along the path (3-D)
  std::vector<double> predicted_t;           ///< [s] predicted samples since the take-off command
  std::vector<double> predicted_speed;       ///< [m/s] predicted speed along the path (3-D)
  std::vector<std::string> waypoint_labels;  ///< the flown waypoints' numbers, in order
  std::vector<double> measured_passage_s;    ///< [s] passage of each waypoint in the log (FlightTimes::passage_s; NaN: unmatched)
  std::vector<double> predicted_passage_s;   ///< [s] the same on the prediction
  std::vector<LegComparison> legs;           ///< legs between consecutive waypoints
  double measured_energy_j = 0.0;            ///< [J] whole flight, measured
  double predicted_energy_j = 0.0;           ///< [J] whole flight, predicted from the mission
  double replay_energy_j = 0.0;              ///< [J] the same model on the logged kinematics
  double measured_time_s = 0.0;              ///< [s] take-off command to landing, measured
  double predicted_time_s = 0.0;             ///< [s] the same, predicted
  double leg_time_mape_pct = 0.0;            ///< [%] mean absolute error of the matched leg times (NaN: none)
  std::string kinematics_note;               ///< where the kinematics differ, one sentence (empty: not shown)
};

/// The mission section of the replay report: which models predicted, and each flight.
struct MissionReplayData {
  std::string model;                         ///< energy model, e.g. "the vehicle file's calibration"
  std::string autopilot;                     ///< flight-behaviour model, e.g. "arducopter-leash"
  std::vector<MissionReplayFlight> flights;  ///< one per --log / --mission pair
};

/// Appends the mission section to `report` (the replay's validation report): per flight, predicted
/// and measured speed over time, leg energies and leg times, the totals and the kinematics / physics
/// split. Throws std::invalid_argument when a flight's series differ in length.
void addMissionReplay(HtmlReport& report, const MissionReplayData& data);

}  // namespace wattswath::report
