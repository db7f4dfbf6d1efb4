#pragma once
/// @file forward_flight.hpp
/// Steady level forward flight of Hwang, Cha & Jung 2018 (Eq. 1-8): thrust balancing weight and
/// drag, tilt, induced velocity of the tilted disk from momentum theory, rotor power T U_i + D U and
/// an efficiency that depends on thrust, as two effects of the energy-model framework.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "wattswath/energy/effect.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace wattswath::energy {

/// Total efficiency eta(T) from electrical input power to ideal rotor power (Hwang Eq. 8), either
/// constant or from a manufacturer's static table of per-rotor thrust against input power.
class EfficiencyCurve {
 public:
  /// A constant efficiency `eta` in (0, 1]; throws std::invalid_argument otherwise.
  static EfficiencyCurve constant(double eta);
  /// From a static table (at least 4 rows, thrust strictly increasing): per-rotor thrust
  /// `thrust_n` [N] and per-rotor electrical input power `power_w` [W]. The input power is
  /// interpolated by a monotone PCHIP spline (Boost.Math) and eta(T) = (T^1.5 / sqrt(2 rho A)) /
  /// P_in(T), the ideal hover rotor power over the input power (Eq. 4-8 at U = 0), with `rotors`
  /// rotors of total disk area `disk_area_m2` [m^2] in air of density `rho` [kg/m^3]. Outside the
  /// table's thrust range eta is held at the end value (see inTableRange). Throws
  /// std::invalid_argument naming the row when the table is malformed or implies eta outside (0, 1].
  static EfficiencyCurve fromThrustPowerTable(std::vector<double> thrust_n, std::vector<double> power_w, int rotors,
                                              double disk_area_m2, double rho);
  /// Efficiency at total thrust `total_thrust_n` [N] [-].
  double operator()(double total_thrust_n) const;
  /// Whether eta is a constant.
  bool isConstant() const { return !table_; }
  /// Whether total thrust `total_thrust_n` [N] lies inside the table (always true when constant).
  bool inTableRange(double total_thrust_n) const;
  /// The same curve with every efficiency multiplied by `factor` (> 0) (for fitting).
  EfficiencyCurve scaled(double factor) const;
  /// The scale factor applied by scaled() (1 for an unscaled curve) [-].
  double scale() const { return scale_; }

 private:
  struct Table;
  double eta_ = 1.0;
  double scale_ = 1.0;
  std::shared_ptr<const Table> table_;
};

/// What the forward-flight model needs: the vehicle's weight, rotors, drag area and efficiency.
struct ForwardFlightParameters {
  double mass_kg = 0.0;           ///< [kg] total mass W/g (vehicle + battery + payload, Eq. 2)
  double gravity_mps2 = 9.81;     ///< [m/s^2] g
  double air_density_kgpm3 = 1.225;  ///< [kg/m^3] rho
  double disk_area_m2 = 0.0;      ///< [m^2] total disk area A = N pi r^2 (Eq. 7)
  double drag_area_m2 = 0.0;      ///< [m^2] S * C_d (Eq. 3)
  EfficiencyCurve efficiency = EfficiencyCurve::constant(1.0);  ///< eta(T) (Eq. 8)
  /// Where `efficiency` comes from, in words, when it is not the vehicle file's extensions.hwang
  /// (empty when it is).
  std::string efficiency_note;

  /// Weight W [N].
  double weightN() const { return mass_kg * gravity_mps2; }
};

/// Model-specific data of a vehicle file's `extensions.hwang` object (data/README.md).
struct HwangExtension {
  double airframe_mass_kg = 0.0;  ///< [kg] W_v: vehicle without battery and payload (0 = unknown)
  std::vector<std::string> battery_configurations;  ///< e.g. {"2S", "2S2P", "2S3P"} (Table 3)
  std::string efficiency_source;  ///< where the efficiency numbers come from
};

/// Parses and validates `v.extensions["hwang"]` (absent: defaults). Throws std::invalid_argument
/// naming `extensions.hwang.<field>`, the value and what was expected.
HwangExtension hwangExtension(const Vehicle& v);

/// Forward-flight parameters of vehicle `v` carrying `payload_kg` [kg] (>= 0). The efficiency comes
/// from `extensions.hwang` (`efficiency`, or `thrust_power_table`) and otherwise from
/// eta_mot * eta_prop. Throws std::invalid_argument on bad extension data or a negative payload.
ForwardFlightParameters forwardFlightParameters(const Vehicle& v, double payload_kg = 0.0);

/// Vehicle `v` with its battery replaced by `series` x `parallel` of its pack and its mass set to
/// the airframe mass (extensions.hwang.airframe_mass_kg) plus the packs (Hwang Table 3). Throws
/// std::invalid_argument when the vehicle has no battery or no airframe mass.
Vehicle withBatteryConfiguration(const Vehicle& v, int series, int parallel);

/// Induced velocity U_i [m/s] of a disk of total area `disk_area_m2` [m^2] producing thrust
/// `thrust_n` [N] at forward speed `speed_mps` [m/s], tilted by `tilt_rad` in [0, pi/2) [rad], in
/// air of density `rho` [kg/m^3]: the root of Eq. 5, U_i = T / (2 rho A) / sqrt((U cos th)^2 +
/// (U sin th + U_i)^2). The residual is strictly increasing in U_i, so the root is bracketed in
/// [0, min(sqrt(T/(2 rho A)), T/(2 rho A U))] and found by TOMS 748 (Boost.Math); it always
/// converges. Hover gives sqrt(T/(2 rho A)); high speed tends to T/(2 rho A U).
double inducedVelocity(double thrust_n, double speed_mps, double tilt_rad, double rho, double disk_area_m2);

/// Everything Eq. 1-8 give at one forward speed.
struct ForwardFlightState {
  double speed_mps = 0.0;             ///< [m/s] U
  double drag_n = 0.0;                ///< [N] D = rho/2 S C_d U^2 (Eq. 3)
  double thrust_n = 0.0;              ///< [N] T = sqrt(W^2 + D^2) (Eq. 1)
  double tilt_rad = 0.0;              ///< [rad] theta = atan(D / W) (Eq. 6)
  double induced_velocity_mps = 0.0;  ///< [m/s] U_i (Eq. 5)
  double induced_power_w = 0.0;       ///< [W] T U_i (rotor side)
  double drag_power_w = 0.0;          ///< [W] D U (rotor side)
  double rotor_power_w = 0.0;         ///< [W] P_re,rotor = T U_i + D U (Eq. 4)
  double efficiency = 1.0;            ///< [-] eta(T) (Eq. 8)
  double electrical_power_w = 0.0;    ///< [W] P_re = P_re,rotor / eta (Eq. 8)
};

/// Steady level flight at `speed_mps` [m/s] (>= 0). Throws std::invalid_argument on bad input.
ForwardFlightState forwardFlight(const ForwardFlightParameters& p, double speed_mps);

/// Which part of Eq. 4 an effect carries.
enum class RotorPowerPart {
  Induced,  ///< T U_i / eta(T): holding the weight up (falls with speed)
  Drag      ///< D U / eta(T): pushing the airframe through the air (grows as U^3)
};

/// One part of Hwang's forward-flight electrical power (Eq. 1-8) at the horizontal ground speed
/// of a motion state (still air; acceleration and climb are not part of the model). Coefficients,
/// identical in both parts (fit them tied): "mass" [kg], "disk_area" [m^2], "drag_area" [m^2],
/// "efficiency_scale" [-] (multiplies eta(T)).
class HwangRotorEffect final : public Effect {
 public:
  /// The `part` of the power of a vehicle with parameters `p`.
  HwangRotorEffect(const ForwardFlightParameters& p, RotorPowerPart part);
  std::string name() const override { return part_ == RotorPowerPart::Induced ? "hwang_induced" : "hwang_drag"; }
  std::string meaning() const override;
  double power(const MotionState& s) const override;
  std::unique_ptr<Effect> clone() const override { return std::make_unique<HwangRotorEffect>(*this); }
  /// The parameters with the current coefficient values.
  ForwardFlightParameters parameters() const;

 private:
  ForwardFlightParameters base_;
  RotorPowerPart part_;
};

/// The Hwang et al. model: hwang_induced + hwang_drag for vehicle `v` with `payload_kg` [kg].
EnergyModel hwangModel(const Vehicle& v, double payload_kg = 0.0);

}  // namespace wattswath::energy
