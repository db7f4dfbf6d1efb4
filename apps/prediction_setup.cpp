// How `predict`, `plan` and `replay --mission` fly a mission for a vehicle file (prediction_setup.hpp).
#include "prediction_setup.hpp"

#include "wattswath/calibration/mission_calibration.hpp"

namespace wattswath::apps {
namespace {

/// The setup with the calibration `cal` when there is one and no `given` model, else `given`'s.
PredictionSetup setupWith(const energy::Vehicle& v, const std::string& vehicle_path,
                          const std::optional<calibration::CalibratedModel>& cal, std::optional<energy::EnergyModel> given,
                          double reserve_pct) {
  const bool use_calibration = cal && !given;
  PredictionSetup s{use_calibration ? cal->model : std::move(*given),
                    mission::parseAutopilot(v.autopilot_json, vehicle_path), {}, use_calibration, {}, {}, {}, {}, {}, {}};
  s.settings.reserve_fraction = reserve_pct / 100.0;
  if (!use_calibration) return s;
  s.settings.flight = calibration::calibratedFlight(*cal, s.settings.flight);
  s.disputed_parameter = cal->disputed_parameter;
  s.disputed_values = cal->disputed_values;
  s.disputed_flights = cal->disputed_flights;
  s.disputed_kinds = cal->disputed_kinds;
  s.coverage = cal->coverage;
  s.behaviour_before = cal->behaviour_before;
  return s;
}

}  // namespace

PredictionSetup predictionSetup(const energy::Vehicle& v, const std::string& vehicle_path, const std::string& effects,
                                double reserve_pct) {
  const auto cal = calibration::calibratedModel(v);
  std::optional<energy::EnergyModel> given;
  if (!cal || !effects.empty())
    given = energy::buildModel(v, energy::splitEffectList(effects.empty() ? "hover,kinetic,parasitic_drag" : effects));
  return setupWith(v, vehicle_path, cal, std::move(given), reserve_pct);
}

PredictionSetup predictionSetup(const energy::Vehicle& v, const std::string& vehicle_path, const energy::EnergyModel& given,
                                bool effects_given, double reserve_pct) {
  const auto cal = calibration::calibratedModel(v);
  std::optional<energy::EnergyModel> model;
  if (!cal || effects_given) model = given;
  return setupWith(v, vehicle_path, cal, std::move(model), reserve_pct);
}

}  // namespace wattswath::apps
