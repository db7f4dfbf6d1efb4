#include "wattswath/energy/forward_flight.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>

// Boost 1.74's pchip.hpp calls isnan unqualified; make std::isnan visible at its definition.
using std::isnan;
#include <boost/math/interpolators/pchip.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <nlohmann/json.hpp>

#include "coefficient_util.hpp"

#include "wattswath/energy/battery.hpp"
#include "wattswath/energy/format.hpp"

namespace wattswath::energy {
namespace {

using nlohmann::json;

using detail::formatNumber;

double idealHoverRotorPower(double total_thrust_n, double rho, double disk_area_m2) {
  return std::pow(total_thrust_n, 1.5) / std::sqrt(2.0 * rho * disk_area_m2);  // Eq. 4-5 at U = 0
}

[[noreturn]] void extensionError(const std::string& field, const std::string& value, const std::string& expected) {
  throw std::invalid_argument("field 'extensions.hwang." + field + "' = " + value + ", expected " + expected);
}

json hwangJson(const Vehicle& v) {
  const auto it = v.extensions.find("hwang");
  if (it == v.extensions.end()) return json::object();
  json j = json::parse(it->second);
  if (!j.is_object()) extensionError("", j.dump(), "an object");
  static const std::set<std::string> known = {"airframe_mass_kg", "efficiency", "thrust_power_table",
                                              "battery_configurations", "efficiency_source", "description"};
  for (auto k = j.begin(); k != j.end(); ++k) {
    if (!known.count(k.key())) {
      std::string list;
      for (const auto& n : known) list += (list.empty() ? "" : ", ") + n;
      throw std::invalid_argument("unknown field 'extensions.hwang." + k.key() + "', expected one of: " + list);
    }
  }
  if (j.contains("efficiency") && j.contains("thrust_power_table")) {
    throw std::invalid_argument(
        "fields 'extensions.hwang.efficiency' and 'extensions.hwang.thrust_power_table' are both given, expected one");
  }
  return j;
}

std::vector<double> numberList(const json& j, const std::string& field) {
  if (!j.is_array()) extensionError(field, j.dump(), "a list of numbers");
  std::vector<double> out;
  for (const auto& x : j) {
    if (!x.is_number()) extensionError(field, j.dump(), "a list of numbers");
    out.push_back(x.get<double>());
  }
  return out;
}

}  // namespace

// ---------------------------------------------------------------- efficiency
struct EfficiencyCurve::Table {
  boost::math::interpolators::pchip<std::vector<double>> power_in;  // per-rotor P_in(T_rotor)
  double t_lo, t_hi;   // per-rotor thrust range [N]
  int rotors;
  double rho, area;
  double eta(double total_thrust_n) const {
    const double t = std::clamp(total_thrust_n / rotors, t_lo, t_hi);
    return idealHoverRotorPower(t * rotors, rho, area) / (rotors * power_in(t));
  }
};

EfficiencyCurve EfficiencyCurve::constant(double eta) {
  if (!(std::isfinite(eta) && eta > 0.0 && eta <= 1.0)) {
    throw std::invalid_argument("efficiency = " + formatNumber(eta) + ", expected an efficiency in (0, 1]");
  }
  EfficiencyCurve c;
  c.eta_ = eta;
  return c;
}

EfficiencyCurve EfficiencyCurve::fromThrustPowerTable(std::vector<double> thrust_n, std::vector<double> power_w,
                                                      int rotors, double disk_area_m2, double rho) {
  const std::string where = "thrust_power_table";
  if (thrust_n.size() != power_w.size()) {
    throw std::invalid_argument(where + ": " + std::to_string(thrust_n.size()) + " thrusts but " +
                                std::to_string(power_w.size()) + " powers, expected equal lengths");
  }
  if (thrust_n.size() < 4) {
    throw std::invalid_argument(where + ": " + std::to_string(thrust_n.size()) +
                                " rows, expected at least 4 (monotone PCHIP spline)");
  }
  if (rotors < 1 || !(disk_area_m2 > 0.0) || !(rho > 0.0)) {
    throw std::invalid_argument(where + ": rotors, disk area and air density must be positive");
  }
  for (size_t k = 0; k < thrust_n.size(); ++k) {
    const std::string row = where + " row " + std::to_string(k);
    if (!(std::isfinite(thrust_n[k]) && thrust_n[k] > 0.0) || (k > 0 && !(thrust_n[k] > thrust_n[k - 1]))) {
      throw std::invalid_argument(row + ": thrust = " + formatNumber(thrust_n[k]) + " N, expected positive and increasing");
    }
    if (!(std::isfinite(power_w[k]) && power_w[k] > 0.0)) {
      throw std::invalid_argument(row + ": power = " + formatNumber(power_w[k]) + " W, expected > 0");
    }
    const double eta = idealHoverRotorPower(thrust_n[k] * rotors, rho, disk_area_m2) / (rotors * power_w[k]);
    if (!(eta > 0.0 && eta <= 1.0)) {
      throw std::invalid_argument(row + ": thrust " + formatNumber(thrust_n[k]) + " N at " + formatNumber(power_w[k]) +
                                  " W gives eta = " + formatNumber(eta) +
                                  ", expected (0, 1] (input power below ideal momentum-theory power: check units "
                                  "and that the table is per rotor)");
    }
  }
  const double lo = thrust_n.front(), hi = thrust_n.back();
  EfficiencyCurve c;
  c.table_ = std::make_shared<const Table>(
      Table{boost::math::interpolators::pchip<std::vector<double>>(std::move(thrust_n), std::move(power_w)), lo, hi,
            rotors, rho, disk_area_m2});
  return c;
}

double EfficiencyCurve::operator()(double total_thrust_n) const {
  return scale_ * (table_ ? table_->eta(total_thrust_n) : eta_);
}

bool EfficiencyCurve::inTableRange(double total_thrust_n) const {
  if (!table_) return true;
  const double t = total_thrust_n / table_->rotors;
  return t >= table_->t_lo && t <= table_->t_hi;
}

EfficiencyCurve EfficiencyCurve::scaled(double factor) const {
  if (!(std::isfinite(factor) && factor > 0.0)) {
    throw std::invalid_argument("efficiency scale = " + formatNumber(factor) + ", expected > 0");
  }
  EfficiencyCurve c = *this;
  c.scale_ = scale_ * factor;
  return c;
}

// ---------------------------------------------------------------- vehicle data
HwangExtension hwangExtension(const Vehicle& v) {
  const json j = hwangJson(v);
  HwangExtension x;
  if (j.contains("airframe_mass_kg")) {
    const json& m = j["airframe_mass_kg"];
    if (!m.is_number() || !(m.get<double>() > 0.0) || m.get<double>() > v.mass_kg) {
      extensionError("airframe_mass_kg", m.dump(), "a mass in (0, mass_kg] kg");
    }
    x.airframe_mass_kg = m.get<double>();
  }
  if (j.contains("battery_configurations")) {
    const json& c = j["battery_configurations"];
    if (!c.is_array()) extensionError("battery_configurations", c.dump(), "a list such as [\"2S\", \"2S2P\"]");
    for (const auto& e : c) {
      if (!e.is_string()) extensionError("battery_configurations", c.dump(), "a list of strings such as \"2S2P\"");
      parseBatteryConfiguration(e.get<std::string>());
      x.battery_configurations.push_back(e.get<std::string>());
    }
  }
  if (j.contains("efficiency_source")) {
    if (!j["efficiency_source"].is_string()) extensionError("efficiency_source", j["efficiency_source"].dump(), "a string");
    x.efficiency_source = j["efficiency_source"].get<std::string>();
  }
  return x;
}

ForwardFlightParameters forwardFlightParameters(const Vehicle& v, double payload_kg) {
  if (!(std::isfinite(payload_kg) && payload_kg >= 0.0 && payload_kg <= 1e4)) {
    throw std::invalid_argument("payload = " + formatNumber(payload_kg) + " kg, expected a mass in [0, 10000] kg");
  }
  ForwardFlightParameters p;
  p.mass_kg = v.mass_kg + payload_kg;
  p.gravity_mps2 = v.gravity_mps2;
  p.air_density_kgpm3 = v.air_density_kgpm3;
  p.disk_area_m2 = v.disk_area_m2;
  p.drag_area_m2 = v.drag_area_m2;
  const json j = hwangJson(v);
  if (j.contains("efficiency")) {
    const json& e = j["efficiency"];
    if (!e.is_number() || !(e.get<double>() > 0.0 && e.get<double>() <= 1.0)) {
      extensionError("efficiency", e.dump(), "an efficiency in (0, 1]");
    }
    p.efficiency = EfficiencyCurve::constant(e.get<double>());
  } else if (j.contains("thrust_power_table")) {
    const json& t = j["thrust_power_table"];
    if (!t.is_object() || !t.contains("thrust_n") || !t.contains("power_w")) {
      extensionError("thrust_power_table", t.dump(), "an object {\"thrust_n\": [...], \"power_w\": [...]} per rotor");
    }
    try {
      p.efficiency = EfficiencyCurve::fromThrustPowerTable(numberList(t["thrust_n"], "thrust_power_table.thrust_n"),
                                                           numberList(t["power_w"], "thrust_power_table.power_w"),
                                                           v.rotor_count, v.disk_area_m2, v.air_density_kgpm3);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("extensions.hwang.") + e.what());
    }
  } else {
    // Marins Eq. 4, for which the vehicle file's eta_mot x eta_prop is chosen, is exactly twice ideal
    // momentum theory (docs/reproduction.md): read against it the same vehicle has half that
    // efficiency, and hovers at the power its file gives (the IRIS: 215 W, 225 W measured).
    p.efficiency = EfficiencyCurve::constant(0.5 * v.totalEfficiency());
    p.efficiency_note = "efficiency " + formatNumber(0.5 * v.totalEfficiency()) +
                        ": the vehicle file has no extensions.hwang efficiency, and its eta_mot x eta_prop (" +
                        formatNumber(v.totalEfficiency()) +
                        ") goes with Marins Eq. 4, which is twice ideal momentum theory, so it is halved here and the "
                        "hover power is the file's Marins hover power (docs/reproduction.md)";
  }
  return p;
}

Vehicle withBatteryConfiguration(const Vehicle& v, int series, int parallel) {
  if (!v.battery) throw std::invalid_argument("vehicle '" + v.name + "' has no battery to reconfigure");
  const HwangExtension x = hwangExtension(v);
  if (!(x.airframe_mass_kg > 0.0)) {
    throw std::invalid_argument("vehicle '" + v.name +
                                "': battery configurations need 'extensions.hwang.airframe_mass_kg' (W_v)");
  }
  Vehicle out = v;
  out.battery = makeBattery(v.battery->pack, series, parallel);
  out.mass_kg = x.airframe_mass_kg + out.battery->mass();
  validate(out);
  return out;
}

// ---------------------------------------------------------------- Eq. 1-8
double inducedVelocity(double thrust_n, double speed_mps, double tilt_rad, double rho, double disk_area_m2) {
  if (!(std::isfinite(thrust_n) && thrust_n >= 0.0) || !(std::isfinite(speed_mps) && speed_mps >= 0.0) ||
      !(tilt_rad >= 0.0 && tilt_rad < 0.5 * M_PI) || !(rho > 0.0) || !(disk_area_m2 > 0.0)) {
    throw std::invalid_argument("inducedVelocity: thrust " + formatNumber(thrust_n) + " N, speed " + formatNumber(speed_mps) +
                                " m/s, tilt " + formatNumber(tilt_rad) + " rad, rho " + formatNumber(rho) + ", area " +
                                formatNumber(disk_area_m2) + ": expected T >= 0, U >= 0, tilt in [0, pi/2), rho > 0, A > 0");
  }
  const double c = thrust_n / (2.0 * rho * disk_area_m2);
  const double hover = std::sqrt(c);
  if (c == 0.0) return 0.0;
  // A forward speed below 1e-12 of the hover induced velocity changes U_i by less than that
  // fraction; it is hover (and c / U would overflow as U goes subnormal).
  if (speed_mps <= 1e-12 * hover) return hover;
  const double ux = speed_mps * std::cos(tilt_rad), uz = speed_mps * std::sin(tilt_rad);
  // Residual u - c / sqrt(ux^2 + (uz + u)^2) is strictly increasing for u >= 0 (uz >= 0), negative
  // at 0 and non-negative at both sqrt(c) and c / U (see the header).
  auto f = [&](double u) { return u - c / std::hypot(ux, uz + u); };
  double hi = std::min(hover, c / speed_mps);
  // Non-negative in exact arithmetic; a rounding error can make it a few ulps negative at a tiny
  // forward speed (T 22934 N at U 2.5e-6 m/s: hypot(ux, sqrt(c)) rounds to sqrt(c)), and then the
  // root is hi to within those ulps (NumericalGuards.InducedVelocityFiniteAcrossItsDocumentedRange).
  if (f(hi) <= 0.0) return hi;
  std::uintmax_t iters = 200;
  const auto r = boost::math::tools::toms748_solve(f, 0.0, hi, boost::math::tools::eps_tolerance<double>(50), iters);
  return 0.5 * (r.first + r.second);
}

ForwardFlightState forwardFlight(const ForwardFlightParameters& p, double speed_mps) {
  if (!(std::isfinite(speed_mps) && speed_mps >= 0.0 && speed_mps <= 200.0)) {
    throw std::invalid_argument("forward flight: speed = " + formatNumber(speed_mps) + " m/s, expected [0, 200] m/s");
  }
  if (!(p.mass_kg > 0.0) || !(p.disk_area_m2 > 0.0) || !(p.drag_area_m2 >= 0.0) || !(p.air_density_kgpm3 > 0.0)) {
    throw std::invalid_argument("forward flight: mass, disk area and air density must be > 0 and drag area >= 0");
  }
  ForwardFlightState s;
  const double w = p.weightN();
  s.speed_mps = speed_mps;
  s.drag_n = 0.5 * p.air_density_kgpm3 * p.drag_area_m2 * speed_mps * speed_mps;  // Eq. 3
  s.thrust_n = std::hypot(w, s.drag_n);                                               // Eq. 1
  s.tilt_rad = std::atan2(s.drag_n, w);                                               // Eq. 6
  s.induced_velocity_mps = inducedVelocity(s.thrust_n, speed_mps, s.tilt_rad, p.air_density_kgpm3, p.disk_area_m2);
  s.induced_power_w = s.thrust_n * s.induced_velocity_mps;
  s.drag_power_w = s.drag_n * speed_mps;
  s.rotor_power_w = s.induced_power_w + s.drag_power_w;  // Eq. 4
  s.efficiency = p.efficiency(s.thrust_n);
  s.electrical_power_w = s.rotor_power_w / s.efficiency;  // Eq. 8
  return s;
}

// ---------------------------------------------------------------- effect
HwangRotorEffect::HwangRotorEffect(const ForwardFlightParameters& p, RotorPowerPart part) : base_(p), part_(part) {
  coeffs_.push_back(detail::coef("mass", p.mass_kg, "kg", 1e-6, 1e4, "total mass W/g: vehicle, battery and payload (Eq. 2)"));
  coeffs_.push_back(detail::coef("disk_area", p.disk_area_m2, "m^2", 1e-6, 1e3, "total rotor disk area N pi r^2 (Eq. 7)"));
  coeffs_.push_back(detail::coef("drag_area", p.drag_area_m2, "m^2", 0.0, 100.0, "S * C_d of the airframe (Eq. 3)"));
  coeffs_.push_back(detail::coef("efficiency_scale", 1.0, "-", 1e-3, 10.0, "multiplier on eta(T) (Eq. 8)"));
}

std::string HwangRotorEffect::meaning() const {
  return part_ == RotorPowerPart::Induced
             ? "induced power T U_i / eta(T) of the tilted rotor disk in forward flight (Hwang Eq. 1-8)"
             : "power D U / eta(T) to overcome the airframe drag in forward flight (Hwang Eq. 3-4, 8)";
}

ForwardFlightParameters HwangRotorEffect::parameters() const {
  ForwardFlightParameters p = base_;
  p.mass_kg = coeffs_[0].value;
  p.disk_area_m2 = coeffs_[1].value;
  p.drag_area_m2 = coeffs_[2].value;
  if (coeffs_[3].value != 1.0) p.efficiency = base_.efficiency.scaled(coeffs_[3].value);
  return p;
}

double HwangRotorEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  const double u = std::hypot(s.velocity.x(), s.velocity.y());
  const ForwardFlightState f = forwardFlight(parameters(), u);
  return (part_ == RotorPowerPart::Induced ? f.induced_power_w : f.drag_power_w) / f.efficiency;
}

EnergyModel hwangModel(const Vehicle& v, double payload_kg) {
  const ForwardFlightParameters p = forwardFlightParameters(v, payload_kg);
  EnergyModel m;
  m.add(HwangRotorEffect(p, RotorPowerPart::Induced));
  m.add(HwangRotorEffect(p, RotorPowerPart::Drag));
  return m;
}

}  // namespace wattswath::energy
