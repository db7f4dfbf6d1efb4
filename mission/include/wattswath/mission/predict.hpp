#pragma once
/// @file predict.hpp
/// How much energy and time a mission file will take, and whether it fits the battery: the
/// mission sequenced and flown by the vehicle's autopilot model (flight.hpp), the energy model's
/// effects integrated over the flown trajectory, split by flight phase and by mission item, and
/// the battery discharged along it (energy/battery.hpp, Hwang et al. Eq. 9-15).

#include <array>
#include <string>
#include <vector>

#include "wattswath/energy/battery.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/mission/flight.hpp"

namespace wattswath::mission {

/// Settings of a prediction.
struct PredictSettings {
  FlightSettings flight;           ///< simulation settings of the behaviour model
  double reserve_fraction = 0.25;  ///< [-] share of the usable charge to keep on landing; 0..0.9
  /// [-] extra energy the reserve verdict also checks, for the prediction's own error (0..1): the
  /// uncalibrated predictions of real flights in docs/validation.md are off by up to 9 %
  double energy_margin = 0.10;
  /// true: flight.airframe is taken from the vehicle (airframeOfVehicle); false: as given
  bool airframe_from_vehicle = true;
  /// [m/s] steady wind, where the air moves to (east, north); replaces flight.airframe.wind. The
  /// ArduCopter models fly against the drag at air speed; the energy model's drag is taken at air
  /// speed (its parasitic_drag becomes the wind effect with the same drag area)
  Eigen::Vector2d wind = Eigen::Vector2d::Zero();
  /// true (predict --lenient): an item PX4 or ArduPilot would not fly as predicted (below home,
  /// a frame PX4 refuses) is a warning in MissionPrediction::warnings instead of a MissionError
  bool lenient = false;
};

/// The airframe of vehicle `v`: its file's `extensions.airframe` object ({"drag_linear_per_s",
/// "drag_quadratic_per_m", "response_s"}, as `wattswath vehicle params` identifies them from a log)
/// where given, else the body drag of its drag area (airframeOf). Throws std::invalid_argument
/// naming `source` and the field for a value that is not a number in range.
Airframe airframeOfVehicle(const energy::Vehicle& v, const std::string& source);

/// Energy, time and distance of one part of the flight.
struct Totals {
  double energy_j = 0.0;    ///< [J] electrical energy
  double time_s = 0.0;      ///< [s] duration
  double distance_m = 0.0;  ///< [m] distance flown (3-D)
};

/// One step of the mission as flown.
struct ItemPrediction {
  int step = -1;             ///< index into MissionPrediction::flight.steps
  int item = -1;             ///< index into Mission::items (-1: added by the model, e.g. a take-off)
  int seq = -1;              ///< the item's number in the file (-1 when added)
  std::string command;       ///< MAVLink command name
  double reached_s = 0.0;    ///< [s] since the take-off command, when the autopilot declares it reached (RTL: over home, before its loiter and descent)
  double completed_s = 0.0;  ///< [s] when it moves on (after any hold)
  Totals totals;             ///< energy, time and distance flown while this step was active
};

/// The battery along the flight (when the vehicle file has one).
struct BatteryPrediction {
  bool known = false;              ///< false: the vehicle has no battery; the rest is unset
  double usable_left_end = 0.0;    ///< [-] usable charge left on landing as the autopilot counts it (1 - drawn / usable; 1 full, 0 cut-off)
  double reserve_fraction = 0.0;   ///< [-] reserve asked for
  bool fits = false;               ///< true when the landing leaves at least the reserve
  double energy_margin = 0.0;      ///< [-] extra energy checked for the prediction's error
  double usable_left_end_with_margin = 0.0;  ///< [-] usable charge left on landing with that extra energy
  bool fits_with_margin = false;   ///< true when the reserve is kept with the extra energy too
  bool depleted = false;           ///< true when the cut-off is reached in flight
  bool ends_in_air = false;        ///< true when the mission ends without a landing (the "landing" figures are where it ends)
  double depleted_at_s = 0.0;      ///< [s] when the cut-off is reached (depleted only)
  std::vector<double> t_s;         ///< [s] times of the state-of-charge samples
  std::vector<double> usable_left; ///< [-] usable charge left at t_s as the autopilot counts it (charge drawn against the usable capacity)
  std::vector<double> voltage_v;   ///< [V] terminal voltage at t_s
  std::string verdict;             ///< one plain sentence on the reserve
};

/// A mission predicted from take-off command to landing.
struct MissionPrediction {
  Totals total;                                     ///< the whole flight
  std::array<Totals, kFlightPhaseCount> phases{};   ///< by FlightPhase
  std::vector<ItemPrediction> items;                ///< one per step
  energy::Breakdown breakdown;                      ///< energy by effect and energy phase
  BatteryPrediction battery;                        ///< state of charge (when known)
  FlownMission flight;                              ///< the trajectory
  FlightPieces pieces;                              ///< the trajectory as pieces
  std::vector<double> piece_energy_j;               ///< [J] energy of each piece
  std::vector<std::string> warnings;                ///< from sequencing and the model
};

/// PX4 keeps at most this many mission items on flight-controller hardware (navigation.h
/// NUM_MISSIONS_SUPPORTED on NuttX, 1.13 and later; 2000 before) and refuses a longer upload.
inline constexpr std::size_t kPx4MaxMissionItems = 500;

/// A note when a mission of `items` items (home not counted) is longer than `autopilot` keeps,
/// naming `source`; empty when it fits (ArduPilot's limit depends on the board, so only PX4's is checked).
std::string missionSizeNote(std::size_t items, const AutopilotConfig& autopilot, const std::string& source);

/// Predicts `m` flown by `autopilot` on vehicle `v` with energy model `model`. Throws what
/// sequenceMission and flyMission throw, and std::invalid_argument for settings out of range.
MissionPrediction predictMission(const Mission& m, const energy::Vehicle& v, const energy::EnergyModel& model,
                                 const AutopilotConfig& autopilot, const PredictSettings& s = {});

/// The power drawn along a prediction, take-off to landing: one step per piece, its energy over its
/// duration [W] (what the battery is discharged along).
std::vector<energy::PowerStep> powerProfile(const MissionPrediction& p);

}  // namespace wattswath::mission
