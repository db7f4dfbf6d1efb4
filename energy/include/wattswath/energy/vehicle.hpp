#pragma once
/// @file vehicle.hpp
/// Vehicle descriptions: the physical parameters every energy effect draws its coefficients from.

#include <map>
#include <optional>
#include <string>

namespace wattswath::energy {

/// One battery pack as its datasheet gives it (Hwang et al. 2018, Table 1).
struct BatteryPack {
  double capacity_ah = 0.0;             ///< [A h] nominal capacity C0 of one pack
  double rated_discharge_time_s = 0.0;  ///< [s] rated discharge time t0 of the Peukert law (Eq. 10)
  double voltage_full_v = 0.0;          ///< [V] fully charged voltage V0 of one pack
  double voltage_standard_v = 0.0;      ///< [V] standard voltage Vs at the end of the linear region
  double mass_kg = 0.0;                 ///< [kg] mass of one pack
  double usable_fraction = 0.0;         ///< [-] lambda: fraction of C0 discharged linearly (Eq. 12)
  double peukert_exponent = 1.0;        ///< [-] Peukert coefficient P (about 1.05 for LiPo)
};

/// A battery made of identical packs, `series` in series times `parallel` in parallel.
struct Battery {
  BatteryPack pack;   ///< one pack
  int series = 1;     ///< [-] packs in series (voltages add)
  int parallel = 1;   ///< [-] strings in parallel (capacities add)

  /// Nominal capacity of the whole battery [A h].
  double capacityAh() const { return pack.capacity_ah * parallel; }
  /// Fully charged voltage of the whole battery [V].
  double voltageFull() const { return pack.voltage_full_v * series; }
  /// Standard (end of linear region) voltage of the whole battery [V].
  double voltageStandard() const { return pack.voltage_standard_v * series; }
  /// Mass of all packs [kg].
  double mass() const { return pack.mass_kg * series * parallel; }
  /// Nominal energy, capacity times full voltage [J].
  double nominalEnergyJ() const { return capacityAh() * 3600.0 * voltageFull(); }
};

/// A multirotor vehicle: mass, rotors, efficiencies, drag and manoeuvre limits, in SI units.
/// Loaded from `data/vehicles/*.json` (fields documented in data/README.md).
struct Vehicle {
  std::string name;                   ///< human-readable name
  double mass_kg = 0.0;               ///< [kg] take-off mass including the battery and any payload
  int rotor_count = 0;                ///< [-] number of rotors N
  double rotor_diameter_m = 0.0;      ///< [m] propeller diameter (2 r)
  double disk_area_m2 = 0.0;          ///< [m^2] total rotor disk area A = N pi r^2 (Hwang Eq. 7)
  double motor_efficiency = 0.0;      ///< [-] eta_mot in [0.01, 1] (Marins Eq. 1)
  double propeller_efficiency = 0.0;  ///< [-] eta_prop in [0.01, 1] (Marins Eq. 1)
  double drag_area_m2 = 0.0;          ///< [m^2] C_D times frontal area (Marins Eq. 8; Hwang S*Cd)
  double max_acceleration_mps2 = 0.0; ///< [m/s^2] acceleration and braking magnitude a
  double max_yaw_rate_radps = 0.0;    ///< [rad/s] maximum yaw rate omega_max (Marins Eq. 13)
  double max_speed_mps = 0.0;         ///< [m/s] maximum horizontal speed the planner may use
  double air_density_kgpm3 = 1.225;   ///< [kg/m^3] air density rho
  double gravity_mps2 = 9.81;         ///< [m/s^2] gravitational acceleration g
  std::optional<Battery> battery;     ///< battery, when known (needed for endurance)
  /// Model-specific data: the JSON text of each entry of the file's `extensions` object, keyed by
  /// its name (e.g. "hwang"); each model parses and validates its own entry.
  std::map<std::string, std::string> extensions;
  std::string autopilot_json;  ///< raw JSON text of the file's "autopilot" object (empty when absent); parsed by wattswath::mission

  /// Total propulsive efficiency eta_tot = eta_mot * eta_prop [-] (Marins Eq. 1).
  double totalEfficiency() const { return motor_efficiency * propeller_efficiency; }
  /// Weight m g [N].
  double weightN() const { return mass_kg * gravity_mps2; }
};

/// Throws std::invalid_argument naming the field, its value and the allowed range when `v` is
/// not physically valid. `source` (a file name) is prefixed to the message when not empty.
void validate(const Vehicle& v, const std::string& source = "");

/// Throws std::invalid_argument naming the field ("battery.<name>"), its value and the allowed
/// range when `b` is not a physically valid battery; `source` is prefixed when not empty.
void validateBattery(const Battery& b, const std::string& source = "");

/// Largest vehicle file read [B] (read whole; a vehicle with every autopilot parameter is ~100 kB).
inline constexpr long long kMaxVehicleFileBytes = 16LL * 1024 * 1024;

/// Reads a vehicle JSON file and validates it; throws std::runtime_error naming the file and field
/// (a file over kMaxVehicleFileBytes is refused before it is read).
Vehicle loadVehicle(const std::string& path);

/// Parses a vehicle from JSON text; `source` names it in error messages.
Vehicle parseVehicle(const std::string& json_text, const std::string& source);

/// Serialises a vehicle to JSON text (the same schema loadVehicle reads).
std::string vehicleToJson(const Vehicle& v);

/// Power the rotors deliver to hover by the Marins et al. Eq. 4, P0 = sqrt(2/(rho A)) (m g)^1.5 [W].
/// Note: this is twice ideal momentum theory's T^1.5/sqrt(2 rho A); see docs/reproduction.md.
double marinsRotorPowerW(const Vehicle& v);

/// Ideal momentum-theory hover power T^1.5 / sqrt(2 rho A) [W] (induced velocity at the disk).
double idealHoverPowerW(const Vehicle& v);

/// Electrical hover power P_hov = P0 / eta_tot [W] (Marins Eq. 5).
double marinsHoverPowerW(const Vehicle& v);

}  // namespace wattswath::energy
