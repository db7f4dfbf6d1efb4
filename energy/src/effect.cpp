#include "wattswath/energy/effect.hpp"

#include <cmath>
#include <stdexcept>

#include "coefficient_util.hpp"

namespace wattswath::energy {
using detail::coef;
namespace {

// Gauss-Legendre nodes and weights on [-1, 1].
constexpr double kGl8X[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                             0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
constexpr double kGl8W[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                             0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};


}  // namespace

double integratePower(const Effect& e, const Piece& p, int points) {
  if (p.duration <= 0.0) return 0.0;
  if (points < 1) throw std::invalid_argument("integratePower: points must be >= 1");
  // Composite rule: `points`/8 panels of 8-point Gauss-Legendre (at least one panel).
  const int panels = std::max(1, points / 8);
  const double h = p.duration / panels;
  double sum = 0.0;
  for (int k = 0; k < panels; ++k) {
    const double mid = (k + 0.5) * h;
    for (int i = 0; i < 8; ++i) sum += kGl8W[i] * e.power(stateAt(p, mid + 0.5 * h * kGl8X[i]));
  }
  return 0.5 * h * sum;
}

double Effect::energy(const Piece& p) const { return integratePower(*this, p, 8); }

std::optional<PieceEnergyGradient> Effect::energyGradient(const Piece&) const { return std::nullopt; }

void Effect::setCoefficientValues(const std::vector<double>& values) {
  if (values.size() != coeffs_.size()) {
    throw std::invalid_argument("effect '" + name() + "': expected " + std::to_string(coeffs_.size()) +
                                " coefficient values, got " + std::to_string(values.size()));
  }
  for (size_t i = 0; i < values.size(); ++i) coeffs_[i].value = values[i];
}

double Effect::coefficient(const std::string& n) const {
  for (const auto& c : coeffs_) {
    if (c.name == n) return c.value;
  }
  throw std::out_of_range("effect '" + name() + "' has no coefficient '" + n + "'");
}

// ---------------------------------------------------------------- hover
HoverEffect::HoverEffect(double p_hover_w) {
  coeffs_.push_back(coef("hover_power", p_hover_w, "W", 0.0, 1e6,
                         "electrical power to hold the vehicle's weight in still air"));
}
HoverEffect HoverEffect::fromVehicle(const Vehicle& v) { return HoverEffect(marinsHoverPowerW(v)); }
std::string HoverEffect::meaning() const {
  return "power to hold the weight up: momentum-theory rotor power over total efficiency (Marins Eq. 1-5)";
}
double HoverEffect::power(const MotionState& s) const { return s.airborne ? coeffs_[0].value : 0.0; }
double HoverEffect::energy(const Piece& p) const {
  return p.phase == Phase::Ground ? 0.0 : coeffs_[0].value * p.duration;
}

std::optional<PieceEnergyGradient> HoverEffect::energyGradient(const Piece& p) const {
  PieceEnergyGradient g;
  const double sum = p.v_start + p.v_end;
  if (p.phase == Phase::Ground || p.length <= 0.0 || !(sum > 0.0)) return g;
  // E = P * 2 L / (v0 + v1)
  g.length = 2.0 * coeffs_[0].value / sum;
  g.v_start = g.v_end = -2.0 * coeffs_[0].value * p.length / (sum * sum);
  return g;
}

// ---------------------------------------------------------------- kinetic
KineticEffect::KineticEffect(double m_eff_kg) {
  coeffs_.push_back(coef("effective_mass", m_eff_kg, "kg", 0.0, 1e5,
                         "mass over efficiency: kinetic energy paid per unit of speed-squared change"));
}
KineticEffect KineticEffect::fromVehicle(const Vehicle& v) { return KineticEffect(v.mass_kg / v.totalEfficiency()); }
std::string KineticEffect::meaning() const {
  return "work to change speed, paid when accelerating and again when braking (non-regenerative, Marins Eq. 6)";
}
double KineticEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  return coeffs_[0].value * std::abs(s.velocity.dot(s.acceleration));
}
double KineticEffect::energy(const Piece& p) const {
  if (p.phase == Phase::Ground) return 0.0;
  return 0.5 * coeffs_[0].value * std::abs(p.v_end * p.v_end - p.v_start * p.v_start);
}

std::optional<PieceEnergyGradient> KineticEffect::energyGradient(const Piece& p) const {
  PieceEnergyGradient g;
  if (p.phase == Phase::Ground) return g;
  // E = m_eff / 2 |v1^2 - v0^2|; on a cruise piece both speeds move together and the change stays 0.
  const double change = p.v_end * p.v_end - p.v_start * p.v_start;
  const double sign = change > 0.0 ? 1.0 : (change < 0.0 ? -1.0 : 0.0);
  g.v_start = -coeffs_[0].value * p.v_start * sign;
  g.v_end = coeffs_[0].value * p.v_end * sign;
  return g;
}

// ---------------------------------------------------------------- parasitic drag
ParasiticDragEffect::ParasiticDragEffect(double cda_m2, double rho, double eta, DragIntegration mode)
    : rho_(rho), eta_(eta), mode_(mode) {
  if (!(rho > 0.0) || !(eta > 0.0 && eta <= 1.0)) {
    throw std::invalid_argument("parasitic_drag: air density must be > 0 and efficiency in (0, 1]");
  }
  coeffs_.push_back(coef("drag_area", cda_m2, "m^2", 0.0, 100.0, "drag area C_D A of the airframe"));
}
ParasiticDragEffect ParasiticDragEffect::fromVehicle(const Vehicle& v, DragIntegration mode) {
  return ParasiticDragEffect(v.drag_area_m2, v.air_density_kgpm3, v.totalEfficiency(), mode);
}
std::string ParasiticDragEffect::meaning() const {
  return "work against air resistance, rho/2 C_D A v^3 over efficiency (Marins Eq. 8-9)";
}
double ParasiticDragEffect::power(const MotionState& s) const {
  if (!s.airborne) return 0.0;
  const double v = s.velocity.norm();
  return powerCoefficient() * v * v * v;
}
double ParasiticDragEffect::energy(const Piece& p) const {
  if (p.phase == Phase::Ground || p.length <= 0.0) return 0.0;
  const double k = powerCoefficient();
  if (mode_ == DragIntegration::PaperCruiseSpeed && p.v_cruise > 0.0) return k * p.length * p.v_cruise * p.v_cruise;
  // v^2 is linear in arc length on a constant-acceleration piece: int v^3 dt = int v^2 ds.
  return k * p.length * 0.5 * (p.v_start * p.v_start + p.v_end * p.v_end);
}

std::optional<PieceEnergyGradient> ParasiticDragEffect::energyGradient(const Piece& p) const {
  PieceEnergyGradient g;
  if (p.phase == Phase::Ground || p.length <= 0.0) return g;
  const double k = powerCoefficient();
  if (mode_ == DragIntegration::PaperCruiseSpeed && p.v_cruise > 0.0) {
    g.length = k * p.v_cruise * p.v_cruise;
    g.v_cruise = 2.0 * k * p.length * p.v_cruise;
    return g;
  }
  g.length = k * 0.5 * (p.v_start * p.v_start + p.v_end * p.v_end);
  g.v_start = k * p.length * p.v_start;
  g.v_end = k * p.length * p.v_end;
  return g;
}

// ---------------------------------------------------------------- yaw rate
YawRateEffect::YawRateEffect(double k) {
  coeffs_.push_back(coef("yaw_power", k, "W s/rad", 0.0, 1e4, "extra power per unit of yaw rate"));
}
std::string YawRateEffect::meaning() const {
  return "extra power while yawing, beyond hover (zero in Marins Eq. 14: unbalanced rotors keep hover thrust)";
}
double YawRateEffect::power(const MotionState& s) const {
  return s.airborne ? coeffs_[0].value * std::abs(s.yaw_rate) : 0.0;
}
double YawRateEffect::energy(const Piece& p) const {
  return p.phase == Phase::Ground ? 0.0 : coeffs_[0].value * std::abs(p.yaw_angle);
}

std::optional<PieceEnergyGradient> YawRateEffect::energyGradient(const Piece&) const {
  return PieceEnergyGradient{};  // k |yaw angle| does not depend on length or speeds
}

}  // namespace wattswath::energy
