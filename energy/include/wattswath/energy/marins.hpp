#pragma once
/// @file marins.hpp
/// The closed form of Marins, Cabreira & Ferreira (2018) for one vehicle: the energy of a straight
/// leg (Eq. 6-9, with the exact drag integral as the default) as an inlined fast path, the paper's
/// Eq. 9 with terms switched off (Eq. 11, Fig. 3), and the optimal speed of Eq. 10 as the real root
/// of a cubic. The generic, effect-by-effect path is EnergyModel + buildLegProfile; both agree to
/// rounding (tested), this one is ~50x faster for planners that evaluate many legs.

#include <cmath>
#include <limits>
#include <optional>

#include "wattswath/energy/effect.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::energy {

class EnergyModel;
struct ProfileLimits;

/// Which terms of Marins Eq. 9 to keep (Eq. 11; Fig. 3 plots all three variants).
struct MarinsTerms {
  bool kinetic = true;  ///< keep m v^2 (accelerating and braking)
  bool drag = true;     ///< keep d rho/2 C_D A v^2
};

/// The unique positive real root of c3 x^3 + c2 x^2 + c1 x + c0 = 0 for c3, c2, c1 >= 0, c0 < 0 and
/// not all of c3, c2, c1 zero (one sign change: exactly one positive root, Descartes). Cardano /
/// trigonometric form, polished by Newton steps; bisection fallback when the residual is poor.
/// Throws std::invalid_argument when the coefficients break these conditions.
double positiveCubicRoot(double c3, double c2, double c1, double c0);

/// Marins et al.'s closed form for one vehicle, with its coefficients precomputed.
struct MarinsClosedForm {
  double p0 = 0.0;         ///< [W] rotor power to hover, Eq. 4
  double eta = 1.0;        ///< [-] total efficiency eta_mot * eta_prop, Eq. 1
  double p_hover = 0.0;    ///< [W] electrical hover power P0 / eta, Eq. 5
  double mass = 0.0;       ///< [kg] vehicle mass m
  double m_eff = 0.0;      ///< [kg] m / eta: kinetic energy paid per unit of v^2/2 change (Eq. 6-7)
  double rho_cda = 0.0;    ///< [kg/m] rho * C_D A (Eq. 10's drag coefficient)
  double k_drag = 0.0;     ///< [kg/m] rho/2 * C_D A / eta: electrical drag energy per metre per v^2 (Eq. 9)
  double accel = 1.0;      ///< [m/s^2] acceleration magnitude a
  double decel = 1.0;      ///< [m/s^2] braking magnitude (the paper uses a for both)
  DragIntegration drag = DragIntegration::Exact;  ///< exact integral (default) or the paper's Eq. 9

  /// Coefficients of vehicle `v` (accel = decel = v.max_acceleration_mps2).
  static MarinsClosedForm fromVehicle(const Vehicle& v, DragIntegration drag = DragIntegration::Exact);

  /// The closed form of `model`'s straight-leg energy when its effects are Marins' own only (hover,
  /// kinetic, parasitic drag, yaw rate: any coefficients, either drag integration), braking and
  /// accelerating at `limits`; std::nullopt when any other effect is present. Sets what legEnergy
  /// reads (p_hover, m_eff, k_drag, accel, decel, drag); p0, eta, mass and rho_cda are NaN, since a
  /// model does not say how its hover power splits into rotor power and efficiency.
  static std::optional<MarinsClosedForm> forLegsOf(const EnergyModel& model, const ProfileLimits& limits);

  /// Energy of a straight level leg of `d` [m] entered at `ve`, cruising at `vc`, left at `vx` [m/s]
  /// [J]: the same profile as buildLegProfile (trapezoid, triangle, valley) and the same numbers as
  /// marinsModel() over it, without allocation or virtual calls. NaN when the leg cannot be flown.
  double legEnergy(double d, double ve, double vc, double vx) const {
    const double e2 = ve * ve, c2 = vc * vc, x2 = vx * vx;
    const double au = accel, ad = decel;
    const double d1 = vc >= ve ? (c2 - e2) / (2.0 * au) : (e2 - c2) / (2.0 * ad);
    const double d3 = vx >= vc ? (x2 - c2) / (2.0 * au) : (c2 - x2) / (2.0 * ad);
    const double paper_drag = k_drag * d * c2;
    if (d1 + d3 <= d && vc > 0.0) {  // trapezoid: change, cruise, change
      const double t = std::abs(vc - ve) / (vc >= ve ? au : ad) + (d - d1 - d3) / vc +
                       std::abs(vx - vc) / (vx >= vc ? au : ad);
      const double kin = 0.5 * m_eff * (std::abs(c2 - e2) + std::abs(x2 - c2));
      const double drg = drag == DragIntegration::Exact
                             ? k_drag * (0.5 * d1 * (e2 + c2) + (d - d1 - d3) * c2 + 0.5 * d3 * (c2 + x2))
                             : paper_drag;
      return p_hover * t + kin + drg;
    }
    const double slack = 4e-9 * std::fmax(std::fmax(e2, x2), 1.0);
    if (ve <= vc && vx <= vc) {  // triangle: the peak stays below cruise
      const double p2 = (2.0 * d * au * ad + e2 * ad + x2 * au) / (au + ad);
      if (p2 < std::fmax(e2, x2) - slack) return std::numeric_limits<double>::quiet_NaN();
      const double vp = std::sqrt(std::fmax(p2, std::fmax(e2, x2)));
      const double l1 = (vp * vp - e2) / (2.0 * au), l2 = (vp * vp - x2) / (2.0 * ad);
      const double t = (vp - ve) / au + (vp - vx) / ad;
      const double kin = 0.5 * m_eff * (2.0 * vp * vp - e2 - x2);
      const double drg = drag == DragIntegration::Exact
                             ? k_drag * (0.5 * l1 * (e2 + vp * vp) + 0.5 * l2 * (vp * vp + x2))
                             : paper_drag;
      return p_hover * t + kin + drg;
    }
    if (ve >= vc && vx >= vc) {  // valley: entry and exit above cruise, the dip stays above it
      const double m2 = (e2 * au + x2 * ad - 2.0 * d * au * ad) / (au + ad);
      if (m2 > std::fmin(e2, x2) + slack) return std::numeric_limits<double>::quiet_NaN();
      const double vm = std::sqrt(std::fmax(0.0, std::fmin(m2, std::fmin(e2, x2))));
      const double l1 = (e2 - vm * vm) / (2.0 * ad), l2 = (x2 - vm * vm) / (2.0 * au);
      const double t = (ve - vm) / ad + (vx - vm) / au;
      const double kin = 0.5 * m_eff * (e2 + x2 - 2.0 * vm * vm);
      const double drg = drag == DragIntegration::Exact
                             ? k_drag * (0.5 * l1 * (e2 + vm * vm) + 0.5 * l2 * (vm * vm + x2))
                             : paper_drag;
      return p_hover * t + kin + drg;
    }
    return std::numeric_limits<double>::quiet_NaN();
  }

  /// Marins Eq. 9 (Eq. 11 with `terms`): energy of a stop-to-stop leg of `d` [m] at speed `v` [m/s],
  /// drag at cruise speed over the whole leg, accel = decel = a [J].
  double eq9Energy(double d, double v, MarinsTerms terms = {}) const;

  /// Marins Eq. 10: the speed minimising eq9Energy(d, v, terms) [m/s], the positive real root of
  /// (2 m + d rho C_D A) v^3 + (P0 / a) v^2 - d P0 = 0 (terms off drop their coefficient).
  double eq10OptimalSpeed(double d, MarinsTerms terms = {}) const;

  /// Limit of eq10OptimalSpeed as d grows: (P0 / (rho C_D A))^(1/3) [m/s] (infinite without drag).
  double longLegOptimalSpeed() const;
};

}  // namespace wattswath::energy
