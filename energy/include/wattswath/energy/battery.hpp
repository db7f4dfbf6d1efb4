#pragma once
/// @file battery.hpp
/// Battery discharge of Hwang, Cha & Jung 2018 (Eq. 9-15, Figure 3): Peukert effective capacity,
/// a voltage that falls linearly over the usable fraction lambda of the nominal capacity, and a
/// constant-power discharge stepped in time until the residual capacity reaches (1 - lambda) C0.
/// Also a discharge under any power profile (for mission planning) and the usable energy.

#include <string>
#include <utility>
#include <vector>

#include "wattswath/energy/vehicle.hpp"

namespace wattswath::energy {

/// Peukert effective capacity C = C0 (C0 / (i t0))^(P - 1) of the whole battery at current
/// `current_a` [A] (Hwang Eq. 10) [A h]. Throws on a non-positive or non-finite current.
double peukertCapacityAh(const Battery& b, double current_a);

/// Slope k = (V0 - Vs) / (lambda C0) of the linear voltage drop (Hwang Eq. 12) [V/(A h)].
double voltageSlope(const Battery& b);

/// Terminal voltage V = V0 - k (C0 - C_re) at residual capacity `residual_ah` [A h] (Hwang Eq. 11) [V].
double voltageAt(const Battery& b, double residual_ah);

/// Residual capacity at which the discharge stops, (1 - lambda) C0 (Hwang Figure 3, step 5) [A h].
double cutoffResidualAh(const Battery& b);

/// One time step of a discharge.
struct BatterySample {
  double t = 0.0;            ///< [s] time since the start
  double power_w = 0.0;      ///< [W] power drawn during the step ending at t
  double voltage_v = 0.0;    ///< [V] terminal voltage during the step (Eq. 13)
  double current_a = 0.0;    ///< [A] current during the step, P / V (Eq. 14)
  double residual_ah = 0.0;  ///< [A h] residual capacity at t (Eq. 15)
  double usable_left = 0.0;  ///< [-] (C_re - (1 - lambda) C0) / (lambda C0): 1 = full (may exceed 1 at
                             ///< low current, where Peukert's effective capacity exceeds C0), 0 = cut-off
};

/// Outcome of a discharge.
struct EnduranceResult {
  double endurance_s = 0.0;          ///< [s] time until the residual reaches the cut-off (or the profile ends)
  double energy_j = 0.0;             ///< [J] electrical energy delivered until then
  double charge_ah = 0.0;            ///< [A h] charge delivered until then
  bool depleted = false;             ///< true when the cut-off was reached
  double final_residual_ah = 0.0;    ///< [A h] residual capacity at the end
  std::vector<BatterySample> series; ///< one sample per step (the first at t = 0, before any draw)
};

/// Settings of the time-stepped discharge.
struct DischargeSettings {
  double dt_s = 1.0;            ///< [s] time step, in (0, 600]; results converge as dt -> 0 (tested)
  double max_time_s = 7.0 * 86400.0;  ///< [s] safety stop for tiny powers, in (0, 1e8]
  bool keep_series = true;      ///< store the per-step time series
};

/// Endurance at constant electrical power `power_w` [W] (Hwang Figure 3 / Eq. 13-15). The step in
/// which the residual crosses the cut-off is interpolated linearly, so the result is continuous
/// in the power and converges to first order in dt. Throws std::invalid_argument on bad input.
EnduranceResult endurance(const Battery& b, double power_w, double dt = 1.0);

/// Endurance at constant power with full settings (see endurance(b, power, dt)).
EnduranceResult endurance(const Battery& b, double power_w, const DischargeSettings& s);

/// One piece of a power profile: `power_w` [W] drawn for `duration_s` [s].
struct PowerStep {
  double duration_s = 0.0;  ///< [s] >= 0
  double power_w = 0.0;     ///< [W] >= 0 (0: motors off, no draw)
};

/// Discharges `b` (from full) along a power profile, e.g. a mission's per-leg powers, with the
/// same per-step law as Eq. 13-15: C_re = C_eff(i_now) - sum(i dt). Stops at the cut-off
/// (`depleted` = true, `endurance_s` = time of depletion) or at the end of the profile.
EnduranceResult simulateProfile(const Battery& b, const std::vector<PowerStep>& profile,
                                const DischargeSettings& s = {});

/// Usable charge left after sample `s` of a discharge of `b` as an autopilot counts it: the charge
/// drawn so far against the usable capacity, 1 - drawn / (lambda C0) [-] (1 full, at most 1; 0 at
/// the cut-off, the sample where `s.usable_left` reaches 0). `s.usable_left` instead reads the
/// residual at the present current (Peukert): it drops as a draw starts and rises when it stops,
/// which decides the cut-off but is not charge gained or lost.
double countedUsableLeft(const Battery& b, const BatterySample& s);

/// Usable energy of `b` when drawn at constant power `power_w` [W]: power times endurance [J].
/// Depends on the power through Peukert's law and the voltage sag.
double energyAvailableJ(const Battery& b, double power_w, double dt = 1.0);

/// A battery of `series` x `parallel` copies of `pack` (Hwang Table 3: 2S, 2S2P, 2S3P).
Battery makeBattery(const BatteryPack& pack, int series, int parallel);

/// Parses "2S", "2S2P", "3P" (series default 1, parallel default 1) into {series, parallel};
/// throws std::invalid_argument naming the text otherwise.
std::pair<int, int> parseBatteryConfiguration(const std::string& text);

}  // namespace wattswath::energy
