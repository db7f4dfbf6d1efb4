#include "wattswath/energy/marins.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/tolerances.hpp"

namespace wattswath::energy {

double positiveCubicRoot(double c3, double c2, double c1, double c0) {
  if (!(std::isfinite(c3) && std::isfinite(c2) && std::isfinite(c1) && std::isfinite(c0)) || c3 < 0.0 ||
      c2 < 0.0 || c1 < 0.0 || !(c0 < 0.0) || (c3 == 0.0 && c2 == 0.0 && c1 == 0.0)) {
    std::ostringstream os;
    os << "positiveCubicRoot: expected c3, c2, c1 >= 0 (not all 0) and c0 < 0, got " << c3 << ", " << c2 << ", "
       << c1 << ", " << c0;
    throw std::invalid_argument(os.str());
  }
  auto f = [&](double x) { return ((c3 * x + c2) * x + c1) * x + c0; };
  auto df = [&](double x) { return (3.0 * c3 * x + 2.0 * c2) * x + c1; };
  // Every term is >= 0 for x > 0, so the root of each single term bounds the root from above.
  double upper = std::numeric_limits<double>::infinity();
  if (c3 > 0.0) upper = std::min(upper, std::cbrt(-c0 / c3));
  if (c2 > 0.0) upper = std::min(upper, std::sqrt(-c0 / c2));
  if (c1 > 0.0) upper = std::min(upper, -c0 / c1);
  double x = upper;
  // Cardano is accurate unless the shift b/3 (or c) dwarfs the root (catastrophic cancellation).
  if (c3 > 0.0 && c2 / c3 < 1e3 * upper && c1 / c3 < 1e6 * upper * upper) {
    // x = t - b/3 gives t^3 + p t + q = 0.
    const double b = c2 / c3, c = c1 / c3, d = c0 / c3;
    const double p = c - b * b / 3.0;
    const double q = 2.0 * b * b * b / 27.0 - b * c / 3.0 + d;
    const double disc = q * q / 4.0 + p * p * p / 27.0;
    if (disc >= 0.0) {  // one real root (Cardano)
      const double s = std::sqrt(disc);
      x = std::cbrt(-q / 2.0 + s) + std::cbrt(-q / 2.0 - s) - b / 3.0;
    } else {  // three real roots: the largest is the positive one (the others are negative)
      const double r = std::sqrt(-p / 3.0);
      const double phi = std::acos(std::clamp(-q / (2.0 * r * r * r), -1.0, 1.0));
      x = 2.0 * r * std::cos(phi / 3.0) - b / 3.0;
    }
    if (!(x > 0.0) || !(x <= upper)) x = upper;
  }
  // Newton polish. f is increasing and convex on x > 0, so from the upper bound it converges
  // monotonically; from Cardano's value it only removes rounding.
  for (int i = 0; i < 200; ++i) {
    const double step = f(x) / df(x);
    x -= step;
    if (!(std::abs(step) > 4.0 * std::numeric_limits<double>::epsilon() * x)) break;
  }
  const double magnitude = std::abs(c0) + c1 * std::abs(x) + c2 * x * x + c3 * std::abs(x * x * x);
  if (!(x > 0.0) || !std::isfinite(x) || std::abs(f(x)) > 1e-12 * magnitude) {
    // Robust fallback: bisection on [0, upper]; f(0) = c0 < 0 <= f(upper) and f is increasing.
    double lo = 0.0, hi = upper;
    for (int i = 0; i < 2000 && hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      (f(mid) < 0.0 ? lo : hi) = mid;
    }
    x = 0.5 * (lo + hi);
  }
  return x;
}

MarinsClosedForm MarinsClosedForm::fromVehicle(const Vehicle& v, DragIntegration drag) {
  validate(v);
  MarinsClosedForm m;
  m.p0 = marinsRotorPowerW(v);
  m.eta = v.totalEfficiency();
  m.p_hover = m.p0 / m.eta;
  m.mass = v.mass_kg;
  m.m_eff = v.mass_kg / m.eta;
  m.rho_cda = v.air_density_kgpm3 * v.drag_area_m2;
  m.k_drag = 0.5 * m.rho_cda / m.eta;
  m.accel = m.decel = v.max_acceleration_mps2;
  m.drag = drag;
  return m;
}

std::optional<MarinsClosedForm> MarinsClosedForm::forLegsOf(const EnergyModel& model, const ProfileLimits& limits) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  MarinsClosedForm m;
  m.p0 = m.eta = m.mass = m.rho_cda = kNaN;
  m.p_hover = m.m_eff = m.k_drag = 0.0;  // an absent effect contributes nothing
  m.accel = limits.acceleration;
  m.decel = limits.deceleration;
  for (const auto& e : model.effects()) {
    if (const auto* h = dynamic_cast<const HoverEffect*>(e.get())) {
      m.p_hover = h->coefficient("hover_power");
    } else if (const auto* k = dynamic_cast<const KineticEffect*>(e.get())) {
      m.m_eff = k->coefficient("effective_mass");
    } else if (const auto* d = dynamic_cast<const ParasiticDragEffect*>(e.get())) {
      m.k_drag = d->powerCoefficient();
      m.drag = d->mode();
    } else if (dynamic_cast<const YawRateEffect*>(e.get()) == nullptr) {
      return std::nullopt;  // a straight leg never yaws, so the yaw effect adds nothing there
    }
  }
  return m;
}

double MarinsClosedForm::eq9Energy(double d, double v, MarinsTerms terms) const {
  if (!(d > 0.0) || !(v > 0.0)) throw std::invalid_argument("Marins Eq. 9: distance and speed must be > 0");
  double e = (d / v + v / accel) * p0;
  if (terms.kinetic) e += mass * v * v;
  if (terms.drag) e += d * 0.5 * rho_cda * v * v;
  return e / eta;
}

double MarinsClosedForm::eq10OptimalSpeed(double d, MarinsTerms terms) const {
  if (!(d > 0.0) || !std::isfinite(d)) {
    throw std::invalid_argument("Marins Eq. 10: distance must be finite and > 0, got " + std::to_string(d));
  }
  const double c3 = (terms.kinetic ? 2.0 * mass : 0.0) + (terms.drag ? d * rho_cda : 0.0);
  return positiveCubicRoot(c3, p0 / accel, 0.0, -d * p0);
}

double MarinsClosedForm::longLegOptimalSpeed() const {
  return rho_cda > 0.0 ? std::cbrt(p0 / rho_cda) : std::numeric_limits<double>::infinity();
}

}  // namespace wattswath::energy
