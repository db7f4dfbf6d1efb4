#include "wattswath/energy/candidate_effects.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "coefficient_util.hpp"

namespace wattswath::energy {
using detail::coef;
namespace {


}  // namespace

// ---------------------------------------------------------------- climb
ClimbEffect::ClimbEffect(double climb_mass_kg, double descent_mass_kg, double g) : g_(g) {
  coeffs_.push_back(coef("climb_mass", climb_mass_kg, "kg", 0.0, 1e3,
                         "mass over climb efficiency: electrical power per unit climb rate, divided by g"));
  coeffs_.push_back(coef("descent_mass", descent_mass_kg, "kg", 0.0, 1e3,
                         "power saved per unit descent rate, divided by g (rotors unloaded by the descent)"));
}
std::string ClimbEffect::meaning() const {
  return "work against gravity while climbing, m g v_z / eta, and the power saved while descending";
}
double ClimbEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  const double vz = s.velocity.z();
  return vz > 0.0 ? coeffs_[0].value * g_ * vz : -coeffs_[1].value * g_ * (-vz);
}

// ---------------------------------------------------------------- wind
WindEffect::WindEffect(double cda_m2, double east, double north, double rho, double eta) : rho_(rho), eta_(eta) {
  if (!(rho > 0.0) || !(eta > 0.0 && eta <= 1.0)) {
    throw std::invalid_argument("wind: air density must be > 0 and efficiency in (0, 1]");
  }
  coeffs_.push_back(coef("drag_area", cda_m2, "m^2", 0.0, 100.0, "drag area C_D A of the airframe"));
  coeffs_.push_back(coef("wind_east", east, "m/s", -40.0, 40.0, "east component of the wind (where the air moves to)"));
  coeffs_.push_back(
      coef("wind_north", north, "m/s", -40.0, 40.0, "north component of the wind (where the air moves to)"));
}
std::string WindEffect::meaning() const {
  return "parasitic drag at air speed in a constant wind, rho/2 C_D A |v - w|^3 / eta (replaces parasitic_drag)";
}
double WindEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  const Eigen::Vector3d air = s.velocity - Eigen::Vector3d(coeffs_[1].value, coeffs_[2].value, 0.0);
  const double va = air.norm();
  return 0.5 * rho_ * coeffs_[0].value * va * va * va / eta_;
}

// ---------------------------------------------------------------- translational lift
TranslationalLiftEffect::TranslationalLiftEffect(double induced_power_w, double induced_velocity_mps) {
  coeffs_.push_back(coef("induced_power", induced_power_w, "W", 0.0, 1e5,
                         "share of hover power that is induced (falls as forward speed brings fresh air)"));
  coeffs_.push_back(coef("induced_velocity", induced_velocity_mps, "m/s", 0.5, 30.0,
                         "induced velocity at hover, sqrt(T / (2 rho A)): the speed scale of the fall"));
}
std::string TranslationalLiftEffect::meaning() const {
  return "translational lift: induced power falls with forward speed (momentum theory, v_i^2 = sqrt(V^4/4 + v_h^4) - "
         "V^2/2)";
}
double TranslationalLiftEffect::inducedRatio(double v, double v_h) {
  const double mu2 = (v / v_h) * (v / v_h);
  // nu^2 = sqrt(mu^4/4 + 1) - mu^2/2, written to avoid cancellation at large mu.
  const double nu2 = 1.0 / (std::sqrt(0.25 * mu2 * mu2 + 1.0) + 0.5 * mu2);
  return std::sqrt(nu2);
}
double TranslationalLiftEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  const double v = s.velocity.head<2>().norm();
  return coeffs_[0].value * (inducedRatio(v, coeffs_[1].value) - 1.0);
}

// ---------------------------------------------------------------- load efficiency
LoadEfficiencyEffect::LoadEfficiencyEffect(double thrust_power_w, double efficiency_slope, double g)
    : thrust_power_(thrust_power_w), g_(g) {
  coeffs_.push_back(coef("efficiency_slope", efficiency_slope, "-", -0.9, 0.9,
                         "relative change of total efficiency per unit of load factor (thrust / weight)"));
}
std::string LoadEfficiencyEffect::meaning() const {
  return "power varying with thrust: thrust^1.5 rotor power over an efficiency linear in thrust (Hwang et al. 2018)";
}
double LoadEfficiencyEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  const double n = (s.acceleration + Eigen::Vector3d(0.0, 0.0, g_)).norm() / g_;
  const double denom = std::max(1.0 + coeffs_[0].value * (n - 1.0), 0.05);
  return thrust_power_ * (n * std::sqrt(n) / denom - 1.0);
}

// ---------------------------------------------------------------- payload
PayloadMassEffect::PayloadMassEffect(double payload_kg, double release_time_s, double vehicle_mass_kg,
                                     double hover_power_w)
    : mass_(vehicle_mass_kg), hover_power_(hover_power_w) {
  if (!(vehicle_mass_kg > 0.0)) throw std::invalid_argument("payload_mass: vehicle mass must be > 0");
  coeffs_.push_back(coef("payload_mass", payload_kg, "kg", 0.0, 10.0 * vehicle_mass_kg,
                         "mass carried until the release (or dropped off) at release_time"));
  coeffs_.push_back(coef("release_time", release_time_s, "s", -1e7, 1e7, "log time at which the payload is released"));
}
std::string PayloadMassEffect::meaning() const {
  return "a payload carried until it is released: hover power scales with mass^1.5 (momentum theory)";
}
double PayloadMassEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  const double dm = coeffs_[0].value;
  const double x = (s.t - coeffs_[1].value) / kReleaseWidth;
  const double carried = x > 40.0 ? 0.0 : 1.0 / (1.0 + std::exp(x));  // 1 before release, 0 after
  const double r = 1.0 + dm / mass_;
  return hover_power_ * (r * std::sqrt(r) - 1.0) * carried;
}

// ---------------------------------------------------------------- building models
const std::vector<std::string>& knownEffectNames() {
  static const std::vector<std::string> n = {"hover",   "kinetic",           "parasitic_drag",  "climb",
                                             "wind",    "translational_lift", "load_efficiency", "yaw_rate",
                                             "payload_mass"};
  return n;
}

const std::vector<std::string>& baseEffectNames() {
  static const std::vector<std::string> n = {"hover", "kinetic"};
  return n;
}

std::unique_ptr<Effect> makeEffect(const std::string& name, const Vehicle& v) {
  const double eta = v.totalEfficiency();
  if (name == "hover") return HoverEffect::fromVehicle(v).clone();
  if (name == "kinetic") return KineticEffect::fromVehicle(v).clone();
  if (name == "parasitic_drag") return ParasiticDragEffect::fromVehicle(v).clone();
  if (name == "yaw_rate") return std::make_unique<YawRateEffect>(0.0);
  if (name == "climb") return std::make_unique<ClimbEffect>(v.mass_kg / eta, 0.0, v.gravity_mps2);
  if (name == "wind") return std::make_unique<WindEffect>(v.drag_area_m2, 0.0, 0.0, v.air_density_kgpm3, eta);
  if (name == "translational_lift") {
    const double vh = std::sqrt(v.weightN() / (2.0 * v.air_density_kgpm3 * v.disk_area_m2));
    return std::make_unique<TranslationalLiftEffect>(0.0, vh);
  }
  if (name == "load_efficiency") {
    return std::make_unique<LoadEfficiencyEffect>(marinsHoverPowerW(v), 0.0, v.gravity_mps2);
  }
  if (name == "payload_mass") return std::make_unique<PayloadMassEffect>(0.0, 0.0, v.mass_kg, marinsHoverPowerW(v));
  std::string known;
  for (const auto& k : knownEffectNames()) known += (known.empty() ? "" : ", ") + k;
  throw std::invalid_argument("unknown effect '" + name + "', expected one of: " + known);
}

EnergyModel buildModel(const Vehicle& v, const std::vector<std::string>& names) {
  EnergyModel m;
  for (const auto& n : names) m.add(makeEffect(n, v));
  if (m.has("wind") && m.has("parasitic_drag")) {
    throw std::invalid_argument("effects 'wind' and 'parasitic_drag' together: wind is parasitic drag at air speed, "
                                "use one of them");
  }
  return m;
}

EnergyModel withCandidate(const EnergyModel& m, const std::string& name, const Vehicle& v) {
  EnergyModel out = m;
  auto e = makeEffect(name, v);
  if (name == "wind" && out.has("parasitic_drag")) {
    auto values = e->coefficients();
    std::vector<double> vals;
    for (const auto& c : values) vals.push_back(c.value);
    vals[0] = out.effect("parasitic_drag").coefficient("drag_area");
    e->setCoefficientValues(vals);
    out.remove("parasitic_drag");
  }
  out.add(std::move(e));
  return out;
}

EnergyModel withWind(const EnergyModel& m, const Vehicle& v, double east, double north) {
  EnergyModel out = !m.has("wind") && m.has("parasitic_drag") ? withCandidate(m, "wind", v) : m;
  if (out.has("wind")) {
    Effect& w = out.effect("wind");
    w.setCoefficientValues({w.coefficient("drag_area"), east, north});
  }
  return out;
}

std::vector<std::string> splitEffectList(const std::string& list) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : list + ",") {
    if (c == ',') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else if (c != ' ') {
      cur.push_back(c);
    }
  }
  return out;
}

}  // namespace wattswath::energy
