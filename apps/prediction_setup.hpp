#pragma once
// How `predict`, `plan` and `replay --mission` fly a mission for a vehicle file: the energy model (the file's
// calibration when it has one and no --effects is given, else the listed effects), its autopilot
// and the calibrated flight behaviour. One place, so plan, predict and replay agree.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "wattswath/calibration/coverage.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/mission/predict.hpp"

namespace wattswath::apps {

/// The model, autopilot and settings a prediction for a vehicle uses.
struct PredictionSetup {
  energy::EnergyModel model;            ///< calibrated or built from the effects
  mission::AutopilotConfig autopilot;   ///< the vehicle file's `autopilot` (or firmware defaults)
  mission::PredictSettings settings;    ///< take-off delay and behaviour from the calibration
  bool calibrated = false;              ///< true when the file's calibration is used
  std::string disputed_parameter;       ///< the calibration's flights disagreed on it (empty: no dispute)
  std::vector<double> disputed_values;  ///< each calibration flight's own value of it
  std::vector<std::string> disputed_flights;            ///< their names (empty in older files)
  std::vector<calibration::MissionKind> disputed_kinds;  ///< what each flew (empty in older files)
  /// What the calibration flights flew (nothing without a calibration, or from files before 2026-11-25).
  std::optional<calibration::MissionKind> coverage;
  std::map<std::string, double> behaviour_before;  ///< the calibrated behaviour parameters' values before it
};

/// The prediction setup of vehicle `v` read from `vehicle_path`; `effects` (comma list, empty: the
/// calibration or "hover,kinetic,parasitic_drag"); `reserve_pct` [%] the landing reserve.
PredictionSetup predictionSetup(const energy::Vehicle& v, const std::string& vehicle_path, const std::string& effects,
                                double reserve_pct);

/// As above with the energy model already built: `given` unless the file has a calibration and
/// `effects_given` is false (then the calibration's), as `replay` chooses.
PredictionSetup predictionSetup(const energy::Vehicle& v, const std::string& vehicle_path, const energy::EnergyModel& given,
                                bool effects_given, double reserve_pct);

}  // namespace wattswath::apps
