#pragma once
/// @file marins_paper.hpp
/// The numbers printed in Marins, Cabreira & Ferreira (2018) and their Sec. V-B strategy comparison
/// as a procedure with switches for what the paper appears to have done differently from its own
/// equations. Shared by `wattswath reproduce` (reproduce_marins.cpp) and the reproduction tests.

#include <cmath>

#include "wattswath/energy/marins.hpp"

namespace wattswath::apps::marins {

// ----- numbers printed in the paper (Sec. IV-V)
inline constexpr double kP0 = 125.6;          ///< [W] Eq. 4, Sec. IV
inline constexpr double kPHover = 214.7;      ///< [W] Eq. 5, Sec. IV-A
inline constexpr double kV2 = 10.24;          ///< [m/s] Eq. 3 induced velocity, Sec. IV-A
inline constexpr double kMeasuredHover = 225.0;  ///< [W] hover power measured by Di Franco & Buttazzo [10]
inline constexpr double kVopt600 = 14.9;      ///< [m/s] Eq. 10 at 600 m, Sec. V-B
inline constexpr double kVopt1200 = 16.2;     ///< [m/s] Eq. 10 at 1,200 m, Sec. V-B
inline constexpr double kLeg600 = 15043.0;    ///< [J] Eq. 9, one 600 m leg at 14.9 m/s
inline constexpr double kTurn45 = 265.0;      ///< [J] Eq. 14, beta = 45 deg
inline constexpr double kTotal1 = 30351.0;    ///< [J] Eq. 12, strategy 1
inline constexpr double kRadius = 7.7;        ///< [m] R = v / omega_max
inline constexpr double kL2 = 1258.0;         ///< [m] Eq. 15 path length
inline constexpr double kTime2 = 78.0;        ///< [s] "about 78 seconds"
inline constexpr double kHover2 = 18337.0;    ///< [J] Eq. 16 hover term
inline constexpr double kDrag2 = 6750.0;      ///< [J] Eq. 16 drag term
inline constexpr double kTotal2 = 25087.0;    ///< [J] strategy 2
inline constexpr double kTable5Distance[3] = {300.0, 600.0, 1200.0};  ///< [m] Table V rows
inline constexpr double kTable5Angle[4] = {30.0, 45.0, 60.0, 90.0};   ///< [deg] Table V columns
/// [%] Table V: energy reduction of strategy 2, [distance][angle].
inline constexpr double kTable5[3][4] = {{33.6, 28.7, 31.4, 29.6}, {20.6, 17.3, 19.1, 17.9}, {11.1, 9.2, 10.2, 9.5}};

/// How the Sec. V-B procedure is evaluated.
struct Procedure {
  bool angle_as_radians = false;  ///< evaluate cos/sin of Eq. 15 at beta read as radians (spreadsheet COS(45))
  double turn_power = 0.0;        ///< [W] power of the turn in place, Eq. 14 (P_hov)
  double rounded_hover_power = 0.0;  ///< [W] hover power of Eq. 16's first term (P_hov)
};

/// The Sec. V-B numbers for one distance and angle.
struct Strategies {
  double v1 = 0.0;       ///< [m/s] Eq. 10 at d
  double leg = 0.0;      ///< [J] Eq. 9, one leg
  double turn = 0.0;     ///< [J] Eq. 14
  double total1 = 0.0;   ///< [J] Eq. 12
  double v2 = 0.0;       ///< [m/s] Eq. 10 at 2 d (the paper's L2 ~ 2 d approximation)
  double radius = 0.0;   ///< [m] v2 / omega_max
  double l2 = 0.0;       ///< [m] 2 d + Eq. 15
  double time2 = 0.0;    ///< [s] L2 / v2
  double hover2 = 0.0;   ///< [J] Eq. 16 first term
  double drag2 = 0.0;    ///< [J] Eq. 16 second term, with 1/eta as in Eq. 9
  double total2 = 0.0;   ///< [J] Eq. 16
  double saving = 0.0;   ///< [%] 100 (E1 - E2) / E1
};

/// Marins Sec. V-B for legs of `d` [m] at angle `beta_deg` [deg], closed form `m` (paper drag),
/// yaw rate `w` [rad/s], evaluated as `p` says.
inline Strategies strategies(const energy::MarinsClosedForm& m, double w, double d, double beta_deg,
                             const Procedure& p) {
  Strategies s;
  const double beta = beta_deg * M_PI / 180.0;
  s.v1 = m.eq10OptimalSpeed(d);
  s.leg = m.eq9Energy(d, s.v1);
  s.turn = (M_PI - beta) / w * p.turn_power;
  s.total1 = 2.0 * s.leg + s.turn;
  s.v2 = m.eq10OptimalSpeed(2.0 * d);
  s.radius = s.v2 / w;
  const double trig = p.angle_as_radians ? beta_deg : beta;
  s.l2 = 2.0 * d + 2.0 * s.radius * (1.0 + std::cos(trig)) / std::sin(trig) + s.radius * (M_PI + beta);
  s.time2 = s.l2 / s.v2;
  s.hover2 = s.time2 * p.rounded_hover_power;
  s.drag2 = s.l2 * m.k_drag * s.v2 * s.v2;
  s.total2 = s.hover2 + s.drag2;
  s.saving = 100.0 * (s.total1 - s.total2) / s.total1;
  return s;
}

/// The hover power the paper's turn energy implies: 265 J over (pi - 45 deg) / omega_max [W].
inline double impliedTurnPower(double w) { return kTurn45 / ((M_PI - M_PI / 4.0) / w); }

/// The hover power the paper's Strategy 2 hover term implies: 18,337 J over 1,258 m / 16.2 m/s [W].
inline double impliedRoundedHoverPower() { return kHover2 / (kL2 / kVopt1200); }

}  // namespace wattswath::apps::marins
