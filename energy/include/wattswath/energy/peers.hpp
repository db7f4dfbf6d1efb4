#pragma once
/// @file peers.hpp
/// Peer power models users compare against, as effects of the same framework: Di Franco &
/// Buttazzo's measured IRIS+ model, the rotary-wing model of Zeng, Xu & Zhang (2019) and the
/// multirotor model of Liu, Sengupta & Kurzhanskiy (2017).

#include <memory>
#include <string>
#include <vector>

#include "wattswath/energy/effect.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::energy {

/// Evaluates a polynomial with coefficients highest power first (MATLAB polyval order) at `x`.
double polyval(const std::vector<double>& coefficients, double x);

// ---------------------------------------------------------------- Di Franco & Buttazzo
/// Di Franco & Buttazzo's measured IRIS+ model (repository carmelodfr/iris3DR_energy_model, MIT):
/// polynomials fitted to measured electrical power. Not physical: valid for the IRIS+ only.
struct DiFrancoModel {
  std::vector<double> level_power;        ///< P(v) [W] at constant horizontal speed v [m/s], highest power first
  std::vector<double> accelerate_power;   ///< P(v) [W] while accelerating at `acceleration_mps2` through speed v
  std::vector<double> decelerate_power;   ///< P(x) [W] while braking, x = decelerate_reference_mps - v
  double decelerate_reference_mps = 15.0; ///< [m/s] the substitution x -> 15 - v of the original code
  double acceleration_mps2 = 1.0;         ///< [m/s^2] acceleration and braking magnitude (PX4 default)
  double climb_speed_mps = 0.0;           ///< [m/s] measured vertical climb speed
  double climb_power_w = 0.0;             ///< [W] measured power while climbing
  double descent_speed_mps = 0.0;         ///< [m/s] measured descent speed
  double descent_power_w = 0.0;           ///< [W] measured power while descending
  double yaw_rate_radps = 0.0;            ///< [rad/s] measured yaw rate of a turn in place
  double yaw_power_w = 0.0;               ///< [W] measured power while turning in place

  /// The published coefficients (E_model.json of the repository, commit 4c63a9d).
  static DiFrancoModel published();
  /// Reads the E_model.json format (../shared/data/difranco/E_model.json); throws naming the file/field.
  static DiFrancoModel load(const std::string& path);

  /// Level-flight power P(v) [W] at speed `v` [m/s].
  double levelPower(double v) const;
  /// Energy [J] of a straight leg of `distance_m` [m] flown stop to stop with cruise speed `v`
  /// [m/s] as the original code computes it: integral of the accelerating power over speed up to v,
  /// P(v) over the constant-speed part (distance - v^2/a) / v, and the braking power integral.
  double stopToStopEnergy(double distance_m, double v) const;
  /// Cruise speed [m/s] minimising stopToStopEnergy for `distance_m` [m]: the first zero of
  /// dE/dv in (0, sqrt(a d)] (a triangular profile at most), refined by TOMS 748.
  double stopToStopOptimalSpeed(double distance_m) const;
};

/// The Di Franco model as one effect ("difranco_measured"): climb power above 0.2 m/s climb rate,
/// descent power below -0.2 m/s, yaw power when turning in place, accelerating/braking power
/// while |a| > 0.05 m/s^2, otherwise P(v). Coefficient "scale" [-] multiplies all powers.
class DiFrancoEffect final : public Effect {
 public:
  /// Effect of model `m`.
  explicit DiFrancoEffect(DiFrancoModel m = DiFrancoModel::published());
  std::string name() const override { return "difranco_measured"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<DiFrancoEffect>(*this); }

 private:
  DiFrancoModel m_;
};

// ---------------------------------------------------------------- Zeng, Xu & Zhang
/// Parameters of the rotary-wing model of Zeng, Xu & Zhang, "Energy minimization for wireless
/// communication with rotary-wing UAV", IEEE TWC 2019, Table I (defaults are the published ones).
struct ZengParameters {
  double profile_drag_coefficient = 0.012;  ///< delta [-]
  double air_density_kgpm3 = 1.225;         ///< rho [kg/m^3]
  double rotor_solidity = 0.05;             ///< s [-]
  double disk_area_m2 = 0.503;              ///< A [m^2]
  double blade_angular_velocity_radps = 300.0;  ///< Omega [rad/s]
  double rotor_radius_m = 0.4;              ///< R [m]
  double induced_correction = 0.1;          ///< k [-] incremental correction of induced power
  double weight_n = 20.0;                   ///< W [N]
  double fuselage_drag_ratio = 0.6;         ///< d0 [-]

  /// Blade profile power in hover P0 = delta/8 rho s A Omega^3 R^3 [W].
  double bladeProfilePowerW() const;
  /// Induced power in hover Pi = (1 + k) W^1.5 / sqrt(2 rho A) [W].
  double inducedPowerW() const;
  /// Tip speed U_tip = Omega R [m/s].
  double tipSpeedMps() const;
  /// Mean rotor induced velocity in hover v0 = sqrt(W / (2 rho A)) [m/s].
  double hoverInducedVelocityMps() const;
};

/// Zeng Eq. 12: P(V) = P0 (1 + 3V^2/U_tip^2) + Pi (sqrt(1 + V^4/(4 v0^4)) - V^2/(2 v0^2))^(1/2)
/// + d0 rho s A V^3 / 2 [W] at forward speed `v` [m/s].
double zengPower(const ZengParameters& p, double v);

/// The Zeng model as one effect ("zeng_rotary_wing") of the horizontal speed. Coefficient
/// "scale" [-] multiplies the power.
class ZengRotaryWingEffect final : public Effect {
 public:
  /// Effect with parameters `p`.
  explicit ZengRotaryWingEffect(const ZengParameters& p = {});
  std::string name() const override { return "zeng_rotary_wing"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<ZengRotaryWingEffect>(*this); }

 private:
  ZengParameters p_;
};

// ---------------------------------------------------------------- Liu, Sengupta & Kurzhanskiy
/// Coefficients of Liu, Sengupta & Kurzhanskiy, "A power consumption model for multi-rotor small
/// unmanned aircraft systems", ICUAS 2017; defaults are their IRIS+ fit. Model form (helicopter
/// theory, angle of attack alpha, air speed V, vertical speed v_z, weight W = m g):
///   T   = sqrt((W - c5 (V cos alpha)^2)^2 + (c4 V^2)^2)
///   P_i = k1 T (v_z/2 + sqrt((v_z/2)^2 + T / k2^2))          (induced, incl. climb)
///   P_p = c2 T^1.5 + c3 (V cos alpha)^2 T^0.5                 (profile; c3 = 0 in the fit)
///   P_d = c4 V^3                                              (parasite)
struct LiuParameters {
  double k1 = 0.8554;   ///< [-] induced-power scale
  double k2 = 0.3051;   ///< [sqrt(kg/m)] induced-power thrust scale
  double c2 = 0.3177;   ///< [sqrt(m/kg)] profile power in hover
  double c3 = 0.0;      ///< [sqrt(kg/m)] profile power in forward flight (0 in the IRIS+ fit)
  double c4 = 0.0296;   ///< [kg/m] fuselage drag
  double c5 = 0.0279;   ///< [kg/m] lift of the airframe in forward flight
  double mass_kg = 1.3; ///< [kg] total mass
  double gravity_mps2 = 9.81;  ///< [m/s^2] g
};

/// Liu et al. power [W] at air speed `v` [m/s], vertical speed `v_z` [m/s] and angle of attack
/// `alpha` [rad] (0: level flight, as used here).
double liuPower(const LiuParameters& p, double v, double v_z = 0.0, double alpha = 0.0);

/// The Liu model as one effect ("liu_2017") of the ground speed and climb rate (still air,
/// alpha = 0). Coefficients k1, k2, c2, c4, c5 as in LiuParameters.
class LiuEffect final : public Effect {
 public:
  /// Effect with parameters `p`.
  explicit LiuEffect(const LiuParameters& p = {});
  std::string name() const override { return "liu_2017"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<LiuEffect>(*this); }

 private:
  LiuParameters base_;
};

/// A model holding one peer effect.
EnergyModel singleEffectModel(const Effect& e);

}  // namespace wattswath::energy
