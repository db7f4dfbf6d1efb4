#include "wattswath/energy/peers.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/io/strict_json.hpp"
#include "wattswath/io/text_file.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <boost/math/tools/toms748_solve.hpp>
#include <nlohmann/json.hpp>

#include "coefficient_util.hpp"

namespace wattswath::energy {
namespace {

double polyder(const std::vector<double>& c, double x) {
  double d = 0.0;
  const size_t n = c.size();
  for (size_t k = 0; k + 1 < n; ++k) d = d * x + c[k] * static_cast<double>(n - 1 - k);
  return d;
}

// Integral from 0 to x of the polynomial.
double polyint(const std::vector<double>& c, double x) {
  double s = 0.0;
  const size_t n = c.size();
  for (size_t k = 0; k < n; ++k) s = s * x + c[k] / static_cast<double>(n - k);
  return s * x;
}

}  // namespace

double polyval(const std::vector<double>& c, double x) {
  double s = 0.0;
  for (double a : c) s = s * x + a;
  return s;
}

// ---------------------------------------------------------------- Di Franco
DiFrancoModel DiFrancoModel::published() {
  DiFrancoModel m;
  m.level_power = {0.003683806457168736, 0.02254081880192812, -0.6962411567465551, 0.32981881218628495,
                   221.2786072982807};
  m.accelerate_power = {2.0278506913465286e-05, 0.014859611872955931, -0.46042074697189045, 5.152279814553939,
                        -21.182532841734336, 233.59704981556033};
  m.decelerate_power = {0.01072166051486935, -0.49382831070964694, 8.343857073684925, -57.737401560222374,
                        341.87228951032466};
  m.climb_speed_mps = 2.0912162162162167;
  m.climb_power_w = 249.01213766816142;
  m.descent_speed_mps = 1.2794117647058822;
  m.descent_power_w = 212.4678513196481;
  m.yaw_rate_radps = 0.6283185307179586;
  m.yaw_power_w = 220.2112745098039;
  return m;
}

DiFrancoModel DiFrancoModel::load(const std::string& path) {
  constexpr int kMaxDepth = 16;  // the model file is a flat object of numbers and lists
  nlohmann::json j;
  try {
    j = io::parseStrictJson(io::readTextFile(path, {kMaxVehicleFileBytes, "peer model files", ""}), kMaxDepth);
  } catch (const io::JsonError& e) {  // io::FileError, a std::runtime_error naming the file, passes
    throw std::runtime_error(path + ": " + e.what());
  }
  auto num = [&](const char* key) {
    if (!j.contains(key) || !j[key].is_number()) throw std::runtime_error(path + ": missing number field '" + key + "'");
    return j[key].get<double>();
  };
  auto list = [&](const char* key) {
    if (!j.contains(key) || !j[key].is_array() || j[key].empty()) {
      throw std::runtime_error(path + ": missing coefficient list '" + key + "'");
    }
    std::vector<double> out;
    for (const auto& x : j[key]) {
      if (!x.is_number()) throw std::runtime_error(path + ": field '" + key + "' must hold numbers");
      out.push_back(x.get<double>());
    }
    return out;
  };
  DiFrancoModel m;
  m.level_power = list("v_coefficents");
  m.accelerate_power = list("pv_acc_coeff");
  m.decelerate_power = list("pv_dec_coeff");
  m.climb_speed_mps = num("v_climb");
  m.climb_power_w = num("p_climb");
  m.descent_speed_mps = num("v_descend");
  m.descent_power_w = num("p_descend");
  m.yaw_rate_radps = num("v_rotate");
  m.yaw_power_w = num("p_rotate");
  return m;
}

double DiFrancoModel::levelPower(double v) const { return polyval(level_power, v); }

double DiFrancoModel::stopToStopEnergy(double d, double v) const {
  if (!(d > 0.0) || !(v > 0.0) || v * v / acceleration_mps2 > d * (1.0 + 1e-12)) {
    throw std::invalid_argument("stopToStopEnergy: distance " + std::to_string(d) + " m cannot be flown stop to stop at " +
                                std::to_string(v) + " m/s (needs v^2/a <= d)");
  }
  const double a = acceleration_mps2, r = decelerate_reference_mps;
  // dt = dv / a on the speed ramps; the braking polynomial is evaluated at r - v.
  const double e_acc = polyint(accelerate_power, v) / a;
  const double e_dec = (polyint(decelerate_power, r) - polyint(decelerate_power, r - v)) / a;
  const double e_const = levelPower(v) * (d - v * v / a) / v;
  return e_acc + e_const + e_dec;
}

double DiFrancoModel::stopToStopOptimalSpeed(double d) const {
  if (!(d > 0.0 && std::isfinite(d))) throw std::invalid_argument("stopToStopOptimalSpeed: distance must be > 0");
  const double a = acceleration_mps2, r = decelerate_reference_mps;
  auto dedv = [&](double v) {
    return polyval(accelerate_power, v) / a + polyval(decelerate_power, r - v) / a +
           polyder(level_power, v) * (d / v - v / a) + levelPower(v) * (-d / (v * v) - 1.0 / a);
  };
  const double vmax = std::sqrt(a * d);
  const int n = 400;
  double prev_v = vmax * 1e-3, prev = dedv(prev_v);
  for (int k = 1; k <= n; ++k) {
    const double v = vmax * (1e-3 + (1.0 - 1e-3) * k / n);
    const double g = dedv(v);
    if (prev < 0.0 && g >= 0.0) {
      std::uintmax_t iters = 200;
      const auto root =
          boost::math::tools::toms748_solve(dedv, prev_v, v, prev, g, boost::math::tools::eps_tolerance<double>(50), iters);
      return 0.5 * (root.first + root.second);
    }
    prev_v = v;
    prev = g;
  }
  return vmax;  // energy still falling at the triangular-profile limit
}

DiFrancoEffect::DiFrancoEffect(DiFrancoModel m) : m_(std::move(m)) {
  coeffs_.push_back(detail::coef("scale", 1.0, "-", 0.0, 10.0, "multiplier on every measured power"));
}

std::string DiFrancoEffect::meaning() const {
  return "measured IRIS+ power: polynomial P(v) in level flight, measured climb, descent and yaw powers "
         "(Di Franco & Buttazzo)";
}

double DiFrancoEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  const double k = coeffs_[0].value;
  const double vz = s.velocity.z();
  const double vh = std::hypot(s.velocity.x(), s.velocity.y());
  if (vz > 0.2) return k * m_.climb_power_w;
  if (vz < -0.2) return k * m_.descent_power_w;
  if (vh < 0.1 && std::abs(s.yaw_rate) > 0.05) return k * m_.yaw_power_w;
  const double along = vh > 1e-9 ? (s.velocity.x() * s.acceleration.x() + s.velocity.y() * s.acceleration.y()) / vh : 0.0;
  if (along > 0.05) return k * polyval(m_.accelerate_power, vh);
  if (along < -0.05) return k * polyval(m_.decelerate_power, m_.decelerate_reference_mps - vh);
  return k * m_.levelPower(vh);
}

// ---------------------------------------------------------------- Zeng
double ZengParameters::bladeProfilePowerW() const {
  const double o = blade_angular_velocity_radps, r = rotor_radius_m;
  return profile_drag_coefficient / 8.0 * air_density_kgpm3 * rotor_solidity * disk_area_m2 * o * o * o * r * r * r;
}
double ZengParameters::inducedPowerW() const {
  return (1.0 + induced_correction) * std::pow(weight_n, 1.5) / std::sqrt(2.0 * air_density_kgpm3 * disk_area_m2);
}
double ZengParameters::tipSpeedMps() const { return blade_angular_velocity_radps * rotor_radius_m; }
double ZengParameters::hoverInducedVelocityMps() const {
  return std::sqrt(weight_n / (2.0 * air_density_kgpm3 * disk_area_m2));
}

double zengPower(const ZengParameters& p, double v) {
  const double ut = p.tipSpeedMps(), v0 = p.hoverInducedVelocityMps();
  const double v2 = v * v, v4 = v2 * v2, v04 = v0 * v0 * v0 * v0;
  const double blade = p.bladeProfilePowerW() * (1.0 + 3.0 * v2 / (ut * ut));
  const double induced = p.inducedPowerW() * std::sqrt(std::sqrt(1.0 + v4 / (4.0 * v04)) - v2 / (2.0 * v0 * v0));
  const double parasite = 0.5 * p.fuselage_drag_ratio * p.air_density_kgpm3 * p.rotor_solidity * p.disk_area_m2 * v2 * v;
  return blade + induced + parasite;
}

ZengRotaryWingEffect::ZengRotaryWingEffect(const ZengParameters& p) : p_(p) {
  coeffs_.push_back(detail::coef("scale", 1.0, "-", 0.0, 10.0, "multiplier on the model power"));
}
std::string ZengRotaryWingEffect::meaning() const {
  return "rotary-wing propulsion power: blade profile, induced and parasite terms (Zeng, Xu & Zhang 2019, Eq. 12)";
}
double ZengRotaryWingEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  return coeffs_[0].value * zengPower(p_, std::hypot(s.velocity.x(), s.velocity.y()));
}

// ---------------------------------------------------------------- Liu
double liuPower(const LiuParameters& p, double v, double v_z, double alpha) {
  const double w = p.mass_kg * p.gravity_mps2;
  const double vc = v * std::cos(alpha);
  const double t = std::hypot(w - p.c5 * vc * vc, p.c4 * v * v);
  const double induced = p.k1 * t * (0.5 * v_z + std::sqrt(0.25 * v_z * v_z + t / (p.k2 * p.k2)));
  const double profile = p.c2 * std::pow(t, 1.5) + p.c3 * vc * vc * std::sqrt(t);
  return induced + profile + p.c4 * v * v * v;
}

LiuEffect::LiuEffect(const LiuParameters& p) : base_(p) {
  coeffs_.push_back(detail::coef("k1", p.k1, "-", 0.0, 100.0, "induced-power scale"));
  coeffs_.push_back(detail::coef("k2", p.k2, "sqrt(kg/m)", 1e-6, 100.0, "induced-power thrust scale"));
  coeffs_.push_back(detail::coef("c2", p.c2, "sqrt(m/kg)", 0.0, 100.0, "profile power in hover"));
  coeffs_.push_back(detail::coef("c4", p.c4, "kg/m", 0.0, 100.0, "fuselage drag"));
  coeffs_.push_back(detail::coef("c5", p.c5, "kg/m", 0.0, 100.0, "airframe lift in forward flight"));
}
std::string LiuEffect::meaning() const {
  return "multirotor power from helicopter theory: induced (with climb), profile and parasite terms "
         "(Liu, Sengupta & Kurzhanskiy 2017)";
}
double LiuEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  LiuParameters p = base_;
  p.k1 = coeffs_[0].value;
  p.k2 = coeffs_[1].value;
  p.c2 = coeffs_[2].value;
  p.c4 = coeffs_[3].value;
  p.c5 = coeffs_[4].value;
  return liuPower(p, std::hypot(s.velocity.x(), s.velocity.y()), s.velocity.z());
}

EnergyModel singleEffectModel(const Effect& e) {
  EnergyModel m;
  m.add(e.clone());
  return m;
}

}  // namespace wattswath::energy
