// The calibration as stored in a vehicle file (extensions.calibration): written by `calibrate`,
// read back by `predict`, `plan` and `replay --mission` (mission_calibration.hpp).
#include <cmath>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/mission/autopilot.hpp"

namespace wattswath::calibration {
namespace {

// The legs and turns of extensions.calibration.coverage (absent in files before 2026-11-25's second
// round: then not compared).
void readCoverageGeometry(const nlohmann::json& c, const std::string& where, MissionKind& k) {
  auto number = [&](const nlohmann::json& v, const std::string& field, double lo) {
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < lo) {
      throw std::invalid_argument(where + "." + field + " = " + v.dump() + ", expected a number of at least " +
                                  std::to_string(static_cast<int>(lo)));
    }
    return v.get<double>();
  };
  if (c.contains("leg_median_m")) {
    const auto& l = c["leg_median_m"];
    if (!l.is_array() || l.size() != 2) {
      throw std::invalid_argument(where + ".leg_median_m = " + l.dump() + ", expected [lowest, highest]");
    }
    k.leg_lo_m = number(l[0], "leg_median_m[0]", 0);
    k.leg_hi_m = number(l[1], "leg_median_m[1]", 0);
  }
  if (c.contains("turn_deg_max")) k.turn_hi_deg = number(c["turn_deg_max"], "turn_deg_max", -1);
  if (c.contains("leg_climb_m_max")) k.climb_hi_m = number(c["leg_climb_m_max"], "leg_climb_m_max", -1);
  if (c.contains("loiter_circles")) k.circles = static_cast<int>(number(c["loiter_circles"], "loiter_circles", 0));
}

// A MissionKind as stored (calibrationToJson's kindToJson); `where` names it in errors.
MissionKind kindFromJson(const nlohmann::json& c, const std::string& where) {
  const bool ok = c.is_object() && c.contains("stop_waypoints") && c["stop_waypoints"].is_number_integer() &&
                  c["stop_waypoints"].get<long>() >= 0 && c.contains("fast_waypoints") &&
                  c["fast_waypoints"].is_number_integer() && c["fast_waypoints"].get<long>() >= 0 && c.contains("speed_mps") &&
                  c["speed_mps"].is_array() && c["speed_mps"].size() == 2 && c["speed_mps"][0].is_number() &&
                  c["speed_mps"][1].is_number() && c["speed_mps"][0].get<double>() >= 0.0 &&
                  c["speed_mps"][1].get<double>() >= c["speed_mps"][0].get<double>();
  if (!ok) {
    throw std::invalid_argument(where + " = " + c.dump() +
                                ", expected {\"stop_waypoints\": N, \"fast_waypoints\": N, \"speed_mps\": [low, high]}");
  }
  MissionKind k{c["stop_waypoints"].get<int>(), c["fast_waypoints"].get<int>(), c["speed_mps"][0].get<double>(),
                c["speed_mps"][1].get<double>()};
  readCoverageGeometry(c, where, k);
  return k;
}

// A MissionKind as stored in extensions.calibration (`coverage`, `per_flight.kinds`).
nlohmann::json kindToJson(const MissionKind& k) {
  nlohmann::json j = {{"stop_waypoints", k.stop_waypoints},
          {"fast_waypoints", k.fast_waypoints},
          {"speed_mps", {k.speed_lo_mps, k.speed_hi_mps}},
          {"leg_median_m", {k.leg_lo_m, k.leg_hi_m}},
          {"turn_deg_max", k.turn_hi_deg},
          {"leg_climb_m_max", k.climb_hi_m}};
  if (k.circles >= 0) j["loiter_circles"] = k.circles;  // absent: not recorded (files before 2026-11-27)
  return j;
}

// per_flight's `flights` and `kinds`, one each per value (absent in older files: nothing read).
void readDisputedKinds(const nlohmann::json& pf, const std::string& where, CalibratedModel& cm) {
  if (!pf.contains("flights") && !pf.contains("kinds")) return;
  const std::size_t n = pf["values"].size();
  if (!pf.contains("flights") || !pf["flights"].is_array() || pf["flights"].size() != n || !pf.contains("kinds") ||
      !pf["kinds"].is_array() || pf["kinds"].size() != n) {
    throw std::invalid_argument(where + " = " + pf.dump() + ", expected \"flights\" (names) and \"kinds\" with one entry per value");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!pf["flights"][i].is_string()) throw std::invalid_argument(where + ".flights holds " + pf["flights"][i].dump() + ", expected names");
    cm.disputed_flights.push_back(pf["flights"][i].get<std::string>());
    cm.disputed_kinds.push_back(kindFromJson(pf["kinds"][i], where + ".kinds[" + std::to_string(i) + "]"));
  }
}

// extensions.calibration's `coverage` and `behaviour_before` (absent in files before 2026-11-25).
void readCoverage(const nlohmann::json& j, const std::string& where, CalibratedModel& cm) {
  if (j.contains("coverage")) cm.coverage = kindFromJson(j["coverage"], where + ".coverage");
  if (j.contains("behaviour_before")) {
    const auto& b = j["behaviour_before"];
    if (!b.is_object()) throw std::invalid_argument(where + ".behaviour_before = " + b.dump() + ", expected {NAME: value}");
    for (const auto& [name, value] : b.items()) {
      if (!value.is_number() || !std::isfinite(value.get<double>())) {
        throw std::invalid_argument(where + ".behaviour_before." + name + " = " + value.dump() + ", expected a number");
      }
      cm.behaviour_before[name] = value.get<double>();
    }
  }
}

}  // namespace

std::string calibrationToJson(const CalibrationResult& r) {
  nlohmann::json j;
  j["takeoff_delay_s"] = r.takeoff_delay_s;
  j["stop_at_waypoints"] = r.stop_at_waypoints;
  j["speed_change_late"] = r.speed_change_late;
  if (r.tracking.measured) {
    j["tracking_error_m"] = {{"horizontal", r.tracking.error.horizontal_m},
                             {"vertical", r.tracking.error.vertical_m},
                             {"samples", r.tracking.samples}};
  }
  j["coverage"] = kindToJson(r.coverage);
  j["behaviour_before"] = r.behaviour_before;
  j["effects"] = r.model.effectNames();
  for (const auto& e : r.model.effects())
    for (const auto& c : e->coefficients()) j["coefficients"][e->name()][c.name] = c.value;
  j["fitted"] = r.fitted;
  j["notes"] = r.notes;
  j["kept_at_start"] = r.kept_at_start;
  j["flights_agree"] = r.flights_agree;
  if (!r.per_flight.empty()) {
    j["per_flight"]["parameter"] = r.acceleration_parameter;
    for (const auto& f : r.per_flight) {
      if (!f.determined) continue;  // fits the joint value as well: no part in a dispute
      j["per_flight"]["values"].push_back(f.value);
      j["per_flight"]["flights"].push_back(f.flight);
      j["per_flight"]["kinds"].push_back(kindToJson(f.kind));
    }
  }
  for (const auto& f : r.after) j["flights"].push_back(f.name);
  return j.dump();
}

std::optional<CalibratedModel> calibratedModel(const energy::Vehicle& v) {
  auto it = v.extensions.find("calibration");
  if (it == v.extensions.end()) return std::nullopt;
  const std::string where = v.name + ": extensions.calibration";
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(it->second);
  } catch (const std::exception& e) {
    throw std::invalid_argument(where + " is not valid JSON: " + e.what());
  }
  if (!j.is_object() || !j.contains("effects") || !j["effects"].is_array()) {
    throw std::invalid_argument(where + " must be an object with an \"effects\" list (as `wattswath calibrate` writes it)");
  }
  CalibratedModel cm;
  std::vector<std::string> names;
  for (const auto& e : j["effects"]) names.push_back(e.get<std::string>());
  cm.model = energy::buildModel(v, names);
  for (const auto& e : cm.model.effects()) {
    std::vector<double> values;
    for (const auto& c : e->coefficients()) {
      const auto& jc = j["coefficients"];
      const bool has = jc.contains(e->name()) && jc[e->name()].contains(c.name) && jc[e->name()][c.name].is_number();
      values.push_back(has ? jc[e->name()][c.name].get<double>() : c.value);
    }
    e->setCoefficientValues(values);
  }
  cm.takeoff_delay_s = j.value("takeoff_delay_s", -1.0);
  cm.stop_at_waypoints = j.value("stop_at_waypoints", false);
  cm.speed_change_late = j.value("speed_change_late", false);
  if (j.contains("tracking_error_m")) {
    const auto& te = j["tracking_error_m"];
    auto metres = [&](const char* key) {
      if (!te.is_object() || !te.contains(key) || !te[key].is_number() || !(te[key].get<double>() >= 0.0) ||
          !(te[key].get<double>() <= 20.0)) {
        throw std::invalid_argument(where + ".tracking_error_m." + key + " = " + (te.is_object() && te.contains(key) ? te[key].dump() : "missing") +
                                    ", expected a distance of 0..20 m");
      }
      return te[key].get<double>();
    };
    cm.tracking_error = {metres("horizontal"), metres("vertical")};
  }
  readCoverage(j, where, cm);
  if (!j.value("flights_agree", true) && j.contains("per_flight")) {
    const auto& pf = j["per_flight"];
    if (!pf.is_object() || !pf.contains("parameter") || !pf["parameter"].is_string() || !pf.contains("values") ||
        !pf["values"].is_array() || pf["values"].size() < 2) {
      throw std::invalid_argument(where + ".per_flight = " + pf.dump() +
                                  ", expected {\"parameter\": NAME, \"values\": [two numbers or more]}");
    }
    cm.disputed_parameter = pf["parameter"].get<std::string>();
    for (const auto& x : pf["values"]) {
      if (!x.is_number() || !std::isfinite(x.get<double>())) {
        throw std::invalid_argument(where + ".per_flight.values holds " + x.dump() + ", expected numbers");
      }
      cm.disputed_values.push_back(x.get<double>());
    }
    readDisputedKinds(pf, where + ".per_flight", cm);
  }
  return cm;
}

mission::FlightSettings calibratedFlight(const CalibratedModel& c, mission::FlightSettings flight) {
  if (c.takeoff_delay_s >= 0.0) flight.takeoff_delay_s = c.takeoff_delay_s;
  flight.stop_at_waypoints = c.stop_at_waypoints;
  flight.speed_change_late = c.speed_change_late;
  flight.tracking_error = c.tracking_error;
  return flight;
}

energy::Vehicle calibratedVehicle(energy::Vehicle v, const CalibrationResult& r) {
  v.autopilot_json = mission::autopilotToJson(r.autopilot);
  v.extensions["calibration"] = calibrationToJson(r);
  return v;
}

}  // namespace wattswath::calibration
