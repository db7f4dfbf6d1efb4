#include "wattswath/energy/vehicle.hpp"
#include "wattswath/energy/format.hpp"
#include "wattswath/io/strict_json.hpp"
#include "wattswath/io/text_file.hpp"

#include <climits>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <set>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

namespace wattswath::energy {
namespace {

using nlohmann::json;

std::string prefix(const std::string& source) { return source.empty() ? "" : source + ": "; }

using detail::formatNumber;

void requireRange(const std::string& source, const char* field, double value, double lo, bool lo_open,
                  double hi, bool hi_open, const char* expected) {
  const bool ok = std::isfinite(value) && (lo_open ? value > lo : value >= lo) &&
                  (hi_open ? value < hi : value <= hi);
  if (!ok) {
    throw std::invalid_argument(prefix(source) + "field '" + field + "' = " + formatNumber(value) +
                                ", expected " + expected);
  }
}

const std::set<std::string>& knownVehicleKeys() {
  static const std::set<std::string> keys = {
      "name", "description", "source", "mass_kg", "rotor_count", "rotor_diameter_m", "disk_area_m2",
      "motor_efficiency", "propeller_efficiency", "drag_area_m2", "max_acceleration_mps2",
      "max_yaw_rate_radps", "max_speed_mps", "air_density_kgpm3", "gravity_mps2", "battery",
      "extensions", "autopilot"};
  return keys;
}

const std::set<std::string>& knownBatteryKeys() {
  static const std::set<std::string> keys = {
      "capacity_ah", "rated_discharge_time_s", "voltage_full_v", "voltage_standard_v", "mass_kg",
      "usable_fraction", "peukert_exponent", "series", "parallel", "description"};
  return keys;
}

void rejectUnknown(const json& j, const std::set<std::string>& known, const std::string& source,
                   const std::string& where) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!known.count(it.key())) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw std::invalid_argument(prefix(source) + "unknown field '" + where + it.key() +
                                  "', expected one of: " + list);
    }
  }
}

double number(const json& j, const char* key, const std::string& source, const std::string& where,
              std::optional<double> fallback = std::nullopt) {
  if (!j.contains(key)) {
    if (fallback) return *fallback;
    throw std::invalid_argument(prefix(source) + "missing field '" + where + key + "' (a number)");
  }
  const json& v = j.at(key);
  if (!v.is_number()) {
    throw std::invalid_argument(prefix(source) + "field '" + where + key + "' = " + v.dump() +
                                ", expected a number");
  }
  return v.get<double>();
}

int integer(const json& j, const char* key, const std::string& source, const std::string& where,
            std::optional<int> fallback = std::nullopt) {
  if (!j.contains(key)) {
    if (fallback) return *fallback;
    throw std::invalid_argument(prefix(source) + "missing field '" + where + key + "' (an integer)");
  }
  const json& v = j.at(key);
  // Range-checked before narrowing: get<int>() would wrap 4294967300 to 4 and accept it.
  const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(INT_MAX)
                                           : v.is_number_integer() && v.get<std::int64_t>() >= INT_MIN &&
                                                 v.get<std::int64_t>() <= INT_MAX;
  if (!fits) {
    throw std::invalid_argument(prefix(source) + "field '" + where + key + "' = " + v.dump() +
                                ", expected an integer" +
                                (v.is_number_integer() ? std::string(" of at most 2147483647 in magnitude") : ""));
  }
  return v.get<int>();
}

}  // namespace

void validate(const Vehicle& v, const std::string& source) {
  requireRange(source, "mass_kg", v.mass_kg, 1e-3, false, 1e4, false, "a mass in [0.001, 10000] kg");
  if (v.rotor_count < 1 || v.rotor_count > 64) {
    throw std::invalid_argument(prefix(source) + "field 'rotor_count' = " + std::to_string(v.rotor_count) +
                                ", expected an integer in [1, 64]");
  }
  // Lower bounds are physical minima, not 0: a 1e-320 m^2 disk or efficiency is "positive" but
  // turns the hover power (Marins Eq. 4-5) into infinity.
  requireRange(source, "rotor_diameter_m", v.rotor_diameter_m, 0.01, false, 20.0, false,
               "a diameter in [0.01, 20] m");
  requireRange(source, "disk_area_m2", v.disk_area_m2, 1e-4, false, 1e3, false, "an area in [0.0001, 1000] m^2");
  requireRange(source, "motor_efficiency", v.motor_efficiency, 0.01, false, 1.0, false,
               "an efficiency in [0.01, 1]");
  requireRange(source, "propeller_efficiency", v.propeller_efficiency, 0.01, false, 1.0, false,
               "an efficiency in [0.01, 1]");
  requireRange(source, "drag_area_m2", v.drag_area_m2, 0.0, false, 100.0, false, "an area in [0, 100] m^2");
  requireRange(source, "max_acceleration_mps2", v.max_acceleration_mps2, 0.05, false, 100.0, false,
               "an acceleration in [0.05, 100] m/s^2 (autopilots accept 0.5 m/s^2 and more; 1e-300 gave 0 s, 0 J legs)");
  requireRange(source, "max_yaw_rate_radps", v.max_yaw_rate_radps, 0.01, false, 100.0, false,
               "a yaw rate in [0.01, 100] rad/s");
  requireRange(source, "max_speed_mps", v.max_speed_mps, 0.1, false, 200.0, false, "a speed in [0.1, 200] m/s");
  requireRange(source, "air_density_kgpm3", v.air_density_kgpm3, 0.01, false, 5.0, false,
               "an air density in [0.01, 5] kg/m^3");
  requireRange(source, "gravity_mps2", v.gravity_mps2, 0.01, false, 30.0, false, "a gravity in [0.01, 30] m/s^2");
  if (v.battery) validateBattery(*v.battery, source);
}

void validateBattery(const Battery& b, const std::string& source) {
  const auto& p = b.pack;
  requireRange(source, "battery.capacity_ah", p.capacity_ah, 0.01, false, 1e4, false, "a capacity in [0.01, 10000] A h");
  requireRange(source, "battery.rated_discharge_time_s", p.rated_discharge_time_s, 1.0, false, 1e7, false,
               "a time in [1, 1e7] s");
  requireRange(source, "battery.voltage_full_v", p.voltage_full_v, 0.1, false, 1e4, false,
               "a voltage in [0.1, 10000] V");
  requireRange(source, "battery.voltage_standard_v", p.voltage_standard_v, 0.0, true, p.voltage_full_v, true,
               "a voltage in (0, voltage_full_v) V");
  requireRange(source, "battery.mass_kg", p.mass_kg, 0.0, false, 1e4, false, "a mass in [0, 10000] kg");
  requireRange(source, "battery.usable_fraction", p.usable_fraction, 0.01, false, 1.0, false, "a fraction in [0.01, 1]");
  requireRange(source, "battery.peukert_exponent", p.peukert_exponent, 1.0, false, 2.0, false,
               "an exponent in [1, 2]");
  if (b.series < 1 || b.parallel < 1 || b.series > 100 || b.parallel > 100) {
    throw std::invalid_argument(prefix(source) + "field 'battery.series'/'battery.parallel' = " +
                                std::to_string(b.series) + "/" + std::to_string(b.parallel) +
                                ", expected integers in [1, 100]");
  }
}

Vehicle parseVehicle(const std::string& json_text, const std::string& source) {
  // Nesting is bounded while parsing (a value nested ~70k deep would otherwise overflow the stack
  // later, in the recursive dump() that quotes it in a message), and a field given twice, which
  // would silently keep the last value, is refused naming the field.
  constexpr int kMaxDepth = 64;
  json j;
  try {
    j = io::parseStrictJson(json_text, kMaxDepth);
  } catch (const io::JsonError& e) {
    switch (e.problem()) {
      case io::JsonProblem::too_deep:
        throw std::invalid_argument(prefix(source) + e.what() + ", expected a flat vehicle object (nesting of at most " +
                                    std::to_string(kMaxDepth) + ")");
      case io::JsonProblem::duplicate_key:
        throw std::invalid_argument(prefix(source) + "field '" + e.key() + "' appears twice, expected each field once");
      case io::JsonProblem::invalid: break;
    }
    throw std::invalid_argument(prefix(source) + e.what());
  }
  if (!j.is_object()) throw std::invalid_argument(prefix(source) + "expected a JSON object at the top level");
  rejectUnknown(j, knownVehicleKeys(), source, "");
  Vehicle v;
  if (j.contains("name")) {
    if (!j["name"].is_string()) throw std::invalid_argument(prefix(source) + "field 'name' must be a string");
    v.name = j["name"].get<std::string>();
  }
  v.mass_kg = number(j, "mass_kg", source, "");
  v.rotor_count = integer(j, "rotor_count", source, "");
  v.rotor_diameter_m = number(j, "rotor_diameter_m", source, "");
  const double r = 0.5 * v.rotor_diameter_m;
  v.disk_area_m2 = number(j, "disk_area_m2", source, "", v.rotor_count * M_PI * r * r);
  v.motor_efficiency = number(j, "motor_efficiency", source, "");
  v.propeller_efficiency = number(j, "propeller_efficiency", source, "");
  v.drag_area_m2 = number(j, "drag_area_m2", source, "");
  v.max_acceleration_mps2 = number(j, "max_acceleration_mps2", source, "");
  v.max_yaw_rate_radps = number(j, "max_yaw_rate_radps", source, "");
  v.max_speed_mps = number(j, "max_speed_mps", source, "");
  v.air_density_kgpm3 = number(j, "air_density_kgpm3", source, "", 1.225);
  v.gravity_mps2 = number(j, "gravity_mps2", source, "", 9.81);
  if (j.contains("battery")) {
    const json& b = j["battery"];
    if (!b.is_object()) throw std::invalid_argument(prefix(source) + "field 'battery' must be an object");
    rejectUnknown(b, knownBatteryKeys(), source, "battery.");
    Battery bat;
    bat.pack.capacity_ah = number(b, "capacity_ah", source, "battery.");
    bat.pack.rated_discharge_time_s = number(b, "rated_discharge_time_s", source, "battery.");
    bat.pack.voltage_full_v = number(b, "voltage_full_v", source, "battery.");
    bat.pack.voltage_standard_v = number(b, "voltage_standard_v", source, "battery.");
    bat.pack.mass_kg = number(b, "mass_kg", source, "battery.");
    bat.pack.usable_fraction = number(b, "usable_fraction", source, "battery.");
    bat.pack.peukert_exponent = number(b, "peukert_exponent", source, "battery.", 1.0);
    bat.series = integer(b, "series", source, "battery.", 1);
    bat.parallel = integer(b, "parallel", source, "battery.", 1);
    v.battery = bat;
  }
  if (j.contains("extensions")) {
    const json& x = j["extensions"];
    if (!x.is_object()) {
      throw std::invalid_argument(prefix(source) + "field 'extensions' = " + x.dump() + ", expected an object");
    }
    for (auto it = x.begin(); it != x.end(); ++it) v.extensions[it.key()] = it.value().dump();
  }
  if (j.contains("autopilot")) {
    const json& a = j["autopilot"];
    if (!a.is_object()) {
      throw std::invalid_argument(prefix(source) + "field 'autopilot' = " + a.dump() +
                                  ", expected an object {\"firmware\", \"version\", \"parameters\"}");
    }
    v.autopilot_json = a.dump();
  }
  validate(v, source);
  return v;
}

Vehicle loadVehicle(const std::string& path) {
  // io::FileError is a std::runtime_error naming the file.
  const std::string text = io::readTextFile(path, {kMaxVehicleFileBytes, "vehicle files", ""});
  try {
    return parseVehicle(text, path);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
}

std::string vehicleToJson(const Vehicle& v) {
  json j = {{"name", v.name},
            {"mass_kg", v.mass_kg},
            {"rotor_count", v.rotor_count},
            {"rotor_diameter_m", v.rotor_diameter_m},
            {"disk_area_m2", v.disk_area_m2},
            {"motor_efficiency", v.motor_efficiency},
            {"propeller_efficiency", v.propeller_efficiency},
            {"drag_area_m2", v.drag_area_m2},
            {"max_acceleration_mps2", v.max_acceleration_mps2},
            {"max_yaw_rate_radps", v.max_yaw_rate_radps},
            {"max_speed_mps", v.max_speed_mps},
            {"air_density_kgpm3", v.air_density_kgpm3},
            {"gravity_mps2", v.gravity_mps2}};
  if (v.battery) {
    const auto& b = *v.battery;
    j["battery"] = {{"capacity_ah", b.pack.capacity_ah},
                    {"rated_discharge_time_s", b.pack.rated_discharge_time_s},
                    {"voltage_full_v", b.pack.voltage_full_v},
                    {"voltage_standard_v", b.pack.voltage_standard_v},
                    {"mass_kg", b.pack.mass_kg},
                    {"usable_fraction", b.pack.usable_fraction},
                    {"peukert_exponent", b.pack.peukert_exponent},
                    {"series", b.series},
                    {"parallel", b.parallel}};
  }
  if (!v.extensions.empty()) {
    json x = json::object();
    for (const auto& [key, text] : v.extensions) x[key] = json::parse(text);
    j["extensions"] = x;
  }
  if (!v.autopilot_json.empty()) j["autopilot"] = json::parse(v.autopilot_json);
  return j.dump(2);
}

double marinsRotorPowerW(const Vehicle& v) {
  return std::sqrt(2.0 / (v.air_density_kgpm3 * v.disk_area_m2)) * std::pow(v.weightN(), 1.5);
}

double idealHoverPowerW(const Vehicle& v) {
  return std::pow(v.weightN(), 1.5) / std::sqrt(2.0 * v.air_density_kgpm3 * v.disk_area_m2);
}

double marinsHoverPowerW(const Vehicle& v) { return marinsRotorPowerW(v) / v.totalEfficiency(); }

}  // namespace wattswath::energy
