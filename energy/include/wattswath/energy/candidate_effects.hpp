#pragma once
/// @file candidate_effects.hpp
/// Candidate physical effects the diagnosis can add to a model (beyond hover, kinetic, drag and
/// yaw of effect.hpp), and building models from effect names. Each effect is one physical term
/// with named coefficients, units, sign bounds and a plain-language meaning.

#include <memory>
#include <string>
#include <vector>

#include "wattswath/energy/effect.hpp"
#include "wattswath/energy/model.hpp"

namespace wattswath::energy {

/// Climb and descent: potential-energy rate over an efficiency while climbing, and a power
/// saving while descending, P = m_c g max(v_z, 0) - m_d g max(-v_z, 0).
/// Coefficients "climb_mass" = m / eta_climb [kg] and "descent_mass" [kg] (both >= 0).
class ClimbEffect final : public Effect {
 public:
  /// Climb effect with `climb_mass_kg` and `descent_mass_kg` [kg], gravity `g` [m/s^2].
  ClimbEffect(double climb_mass_kg, double descent_mass_kg, double g = 9.81);
  std::string name() const override { return "climb"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<ClimbEffect>(*this); }

 private:
  double g_;
};

/// Parasitic drag at air speed in a constant horizontal wind w (where the air moves to):
/// P = rho/2 C_D A |v - w|^3 / eta_tot (Marins Eq. 8 with air speed instead of ground speed).
/// It replaces `parasitic_drag` in a model (buildModel and withCandidate swap them).
/// Coefficients "drag_area" [m^2], "wind_east" [m/s], "wind_north" [m/s].
class WindEffect final : public Effect {
 public:
  /// Wind effect with drag area `cda_m2` [m^2], wind (`east`, `north`) [m/s], density `rho`
  /// [kg/m^3] and total efficiency `eta` [-].
  WindEffect(double cda_m2, double east, double north, double rho, double eta);
  std::string name() const override { return "wind"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<WindEffect>(*this); }

 private:
  double rho_;
  double eta_;
};

/// Translational lift: induced power falls with forward speed V. Momentum theory in level
/// flight (Glauert; Hwang et al. 2018 Eq. 7 with small tilt): v_i^2 = sqrt(V^4/4 + v_h^4) - V^2/2,
/// so P_i(V) = P_i0 v_i / v_h, and this effect adds P_i0 (v_i(V)/v_h - 1) <= 0.
/// Coefficients "induced_power" P_i0 [W] (share of hover power that is induced) and
/// "induced_velocity" v_h [m/s] (hover induced velocity sqrt(T / (2 rho A))).
class TranslationalLiftEffect final : public Effect {
 public:
  /// Translational-lift effect with `induced_power_w` [W] and `induced_velocity_mps` [m/s].
  TranslationalLiftEffect(double induced_power_w, double induced_velocity_mps);
  std::string name() const override { return "translational_lift"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<TranslationalLiftEffect>(*this); }
  /// v_i(V) / v_h for forward speed V [m/s] and hover induced velocity v_h [m/s] [-].
  static double inducedRatio(double v, double v_h);
};

/// Load-dependent efficiency: rotor power scales with thrust^1.5 (momentum theory) and the
/// total efficiency varies linearly with thrust (Hwang et al. 2018 use eta(T)). With the load
/// factor n = |a + g e_z| / g, P = P_t (n^1.5 / (1 + k (n - 1)) - 1), P_t the vehicle's hover
/// power (fixed: to first order only P_t (1.5 - k) is observable, so one of them must be known).
/// Coefficient "efficiency_slope" k [-] (relative change of efficiency per unit of load factor,
/// -0.9..0.9; 0 = constant efficiency, thrust^1.5 scaling only).
class LoadEfficiencyEffect final : public Effect {
 public:
  /// Load effect with hover power `thrust_power_w` [W] (fixed), `efficiency_slope` [-], gravity `g` [m/s^2].
  LoadEfficiencyEffect(double thrust_power_w, double efficiency_slope, double g = 9.81);
  std::string name() const override { return "load_efficiency"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<LoadEfficiencyEffect>(*this); }

 private:
  double thrust_power_;
  double g_;
};

/// A payload of mass dm carried until it is released at time t_r: hover power scales with
/// (m + dm)^1.5 (momentum theory), so before t_r the vehicle draws P_h ((1 + dm/m)^1.5 - 1)
/// more. The release is a smooth step of width kReleaseWidth so the time can be fitted.
/// Coefficients "payload_mass" dm [kg] (>= 0) and "release_time" t_r [s] (log time).
class PayloadMassEffect final : public Effect {
 public:
  /// Payload effect with `payload_kg` [kg] released at `release_time_s` [s], for a vehicle of
  /// mass `vehicle_mass_kg` [kg] whose hover power (without payload) is `hover_power_w` [W].
  PayloadMassEffect(double payload_kg, double release_time_s, double vehicle_mass_kg, double hover_power_w);
  std::string name() const override { return "payload_mass"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<PayloadMassEffect>(*this); }
  /// [s] time constant of the smooth release step (a logistic of this scale).
  static constexpr double kReleaseWidth = 0.5;

 private:
  double mass_;
  double hover_power_;
};

/// Names of every effect buildModel knows, in the order the diagnosis tries candidates.
const std::vector<std::string>& knownEffectNames();

/// The base effects every diagnosed model has: "hover", "kinetic".
const std::vector<std::string>& baseEffectNames();

/// One effect by name with coefficients from vehicle physics (candidates start neutral:
/// wind 0, payload 0, induced power 0, yaw power 0, ...; load_efficiency and climb start from
/// momentum theory and m / eta_tot). Throws std::invalid_argument
/// listing the known names when `name` is unknown.
std::unique_ptr<Effect> makeEffect(const std::string& name, const Vehicle& v);

/// A model of the named effects in order (e.g. {"hover","kinetic","parasitic_drag"}); "wind"
/// and "parasitic_drag" together is an error (wind is drag at air speed). Throws on duplicates.
EnergyModel buildModel(const Vehicle& v, const std::vector<std::string>& names);

/// `m` plus effect `name` from vehicle physics; adding "wind" replaces "parasitic_drag" and
/// keeps its drag area.
EnergyModel withCandidate(const EnergyModel& m, const std::string& name, const Vehicle& v);

/// `m` with its drag taken at air speed in a steady wind `east`, `north` [m/s] (where the air moves
/// to): its `parasitic_drag` becomes the `wind` effect with the same drag area, or its `wind`
/// effect gets this wind. A model with neither is returned unchanged (check `has("wind")`).
EnergyModel withWind(const EnergyModel& m, const Vehicle& v, double east, double north);

/// Splits "a,b,c" into names (spaces ignored).
std::vector<std::string> splitEffectList(const std::string& list);

}  // namespace wattswath::energy
