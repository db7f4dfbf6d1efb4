// How `predict` and `plan` fly a mission for a vehicle file (prediction_setup.hpp).
#include "prediction_setup.hpp"

#include "wattswath/calibration/mission_calibration.hpp"

namespace wattswath::apps {

PredictionSetup predictionSetup(const energy::Vehicle& v, const std::string& vehicle_path, const std::string& effects,
                                double reserve_pct) {
  const auto calibrated = calibration::calibratedModel(v);
  const bool use_calibration = calibrated && effects.empty();
  PredictionSetup s{use_calibration ? calibrated->model
                                    : energy::buildModel(v, energy::splitEffectList(effects.empty() ? "hover,kinetic,parasitic_drag" : effects)),
                    mission::parseAutopilot(v.autopilot_json, vehicle_path), {}, use_calibration, {}, {}, {}, {}, {}, {}};
  s.settings.reserve_fraction = reserve_pct / 100.0;
  if (use_calibration) {
    if (calibrated->takeoff_delay_s >= 0.0) s.settings.flight.takeoff_delay_s = calibrated->takeoff_delay_s;
    s.settings.flight.stop_at_waypoints = calibrated->stop_at_waypoints;
    s.settings.flight.speed_change_late = calibrated->speed_change_late;
    s.settings.flight.tracking_error = calibrated->tracking_error;
    s.disputed_parameter = calibrated->disputed_parameter;
    s.disputed_values = calibrated->disputed_values;
    s.disputed_flights = calibrated->disputed_flights;
    s.disputed_kinds = calibrated->disputed_kinds;
    s.coverage = calibrated->coverage;
    s.behaviour_before = calibrated->behaviour_before;
  }
  return s;
}

}  // namespace wattswath::apps
