// Python bindings of mission calibration: the flight behaviour and energy coefficients fitted to
// logged flights of known missions (calibration/mission_calibration.hpp), as `wattswath calibrate`
// fits them, with the calibrated vehicle ready for predict_mission.
#include "bindings.hpp"

#include <cmath>
#include <utility>

#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/mission/autopilot.hpp"

namespace wattswath::python {
namespace {

namespace cal = calibration;
namespace ms = mission;

// A number, or None when it is not finite (a leg the log never reached).
py::object numberOrNone(double x) { return std::isfinite(x) ? py::object(py::float_(x)) : py::none(); }

py::dict comparisonDict(const cal::FlightComparison& c) {
  py::list legs;
  for (std::size_t k = 0; k < c.measured.leg_s.size() && k < c.predicted.leg_s.size(); ++k)
    legs.append(py::dict(py::arg("leg") = k + 1, py::arg("measured_time_s") = numberOrNone(c.measured.leg_s[k]),
                         py::arg("predicted_time_s") = numberOrNone(c.predicted.leg_s[k]),
                         py::arg("measured_energy_j") = numberOrNone(c.measured.leg_energy_j[k]),
                         py::arg("predicted_energy_j") = numberOrNone(c.predicted.leg_energy_j[k])));
  return py::dict(py::arg("flight") = c.name, py::arg("time_error_pct") = c.time_error_pct,
                  py::arg("energy_error_pct") = c.energy_error_pct,
                  py::arg("leg_time_mape_pct") = numberOrNone(c.leg_time_mape_pct), py::arg("legs_matched") = c.legs_matched,
                  py::arg("measured_time_s") = c.measured.total_s, py::arg("predicted_time_s") = c.predicted.total_s,
                  py::arg("measured_energy_j") = c.measured.energy_j, py::arg("predicted_energy_j") = c.predicted.energy_j,
                  py::arg("legs") = legs);
}

py::list comparisonList(const std::vector<cal::FlightComparison>& cs) {
  py::list out;
  for (const auto& c : cs) out.append(comparisonDict(c));
  return out;
}

// Calibrates `vehicle` on the flights (log, mission) in order, as `wattswath calibrate` does; the
// result's "vehicle" is the vehicle with the fitted autopilot and its extensions.calibration.
py::dict calibrate(const energy::Vehicle& vehicle, const std::vector<logs::FlightLog>& flight_logs,
                   const std::vector<ms::Mission>& missions, const std::string& effects, int evaluations, bool keep_energy,
                   double keep_share, double keep_significance) {
  if (flight_logs.size() != missions.size() || flight_logs.empty()) {
    throw std::invalid_argument("calibrate_missions: " + std::to_string(flight_logs.size()) + " logs and " +
                                std::to_string(missions.size()) + " missions; give one mission per log, in the same order");
  }
  if (evaluations < 10 || evaluations > 5000) {
    throw std::invalid_argument("calibrate_missions: evaluations = " + std::to_string(evaluations) + ", expected 10..5000");
  }
  const energy::EnergyModel model = energy::buildModel(vehicle, energy::splitEffectList(effects));
  const ms::AutopilotConfig ap = ms::parseAutopilot(vehicle.autopilot_json, vehicle.name);
  std::vector<cal::MissionFlight> flights;
  std::vector<std::string> window_notes;
  for (std::size_t i = 0; i < flight_logs.size(); ++i) {
    logs::FlightLog log = flight_logs[i];
    // An autopilot log read whole is compared from the switch into the mission mode to the landing.
    const logs::MissionCut cut = logs::cutToMission(log);
    if (!cut.note.empty()) window_notes.push_back(cut.note);
    flights.push_back({log.source, missions[i], std::move(log)});
  }
  cal::CalibrationSettings cs;
  cs.max_evaluations = evaluations;
  cs.fit_energy = !keep_energy;
  cs.keep_share = keep_share;
  cs.keep_significance = keep_significance;
  const cal::CalibrationResult r = cal::calibrateMissions(flights, vehicle, model, ap, cs);
  const energy::Vehicle out = cal::calibratedVehicle(vehicle, r);
  py::dict params;
  for (const auto& [name, value] : r.autopilot.parameters) params[py::str(name)] = value;
  py::list per_flight;
  for (const auto& f : r.per_flight)
    per_flight.append(py::dict(py::arg("flight") = f.flight, py::arg("parameter") = r.acceleration_parameter,
                               py::arg("value") = f.value, py::arg("misfit_alone") = f.misfit_alone,
                               py::arg("misfit_joint") = f.misfit_joint, py::arg("determined") = f.determined));
  py::dict d;
  d["vehicle"] = out;
  d["parameters"] = params;
  d["takeoff_delay_s"] = r.takeoff_delay_s;
  d["stop_at_waypoints"] = r.stop_at_waypoints;
  d["speed_change_late"] = r.speed_change_late;
  d["tracking_error_m"] = r.tracking.measured ? py::object(py::make_tuple(r.tracking.error.horizontal_m, r.tracking.error.vertical_m))
                                              : py::none();
  d["fitted"] = r.fitted;
  std::vector<std::string> notes = window_notes;
  notes.insert(notes.end(), r.notes.begin(), r.notes.end());
  d["notes"] = notes;
  d["kept_at_start"] = r.kept_at_start;
  d["flights_agree"] = r.flights_agree;
  d["per_flight"] = per_flight;
  d["before"] = comparisonList(r.before);
  d["after"] = comparisonList(r.after);
  return d;
}

}  // namespace

void bindMissionCalibration(py::module_& m) {
  m.def("calibrate_missions", &calibrate, py::arg("vehicle"), py::arg("logs"), py::arg("missions"),
        py::arg("effects") = "hover,kinetic,parasitic_drag,climb,translational_lift", py::arg("evaluations") = 150,
        py::arg("keep_energy") = false, py::arg("keep_share") = 0.01, py::arg("keep_significance") = 0.05,
        "Fits the autopilot's flight behaviour (accelerations, gains, climb and descent speeds, take-off delay, corner "
        "and speed-change rules) and, unless keep_energy, the energy coefficients of `effects` to logged flights "
        "(FlightLog, read_log) of known missions (Mission, read_mission), one mission per log in order, as `wattswath "
        "calibrate` does: dict vehicle (the calibrated Vehicle, for predict_mission), parameters, takeoff_delay_s, "
        "stop_at_waypoints, speed_change_late, tracking_error_m (horizontal, vertical) or None, fitted, notes, "
        "kept_at_start (parameters the flights do not call to change: a return to the start costing at most "
        "keep_share of the time misfit, or not significantly at level keep_significance by an F-test of the nested "
        "fits), flights_agree, per_flight, before and after (per flight: time and energy "
        "errors [%], leg-time MAPE [%], legs).");
}

}  // namespace wattswath::python
