#include "wattswath/planner/battery_use.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "wattswath/energy/battery.hpp"

namespace wattswath::planner {

BatteryUse predictBatteryUse(const FlownPath& flown, const energy::Battery& battery, const BatteryUseSettings& s) {
  std::vector<energy::PowerStep> profile;
  for (size_t i = 0; i < flown.leg_energy.size(); ++i)
    if (flown.leg_time[i] > 0.0) profile.push_back({flown.leg_time[i], flown.leg_energy[i] / flown.leg_time[i]});
  return predictBatteryUse(profile, battery, s);
}

BatteryUse predictBatteryUse(const std::vector<energy::PowerStep>& profile, const energy::Battery& battery,
                             const BatteryUseSettings& s) {
  if (!(s.reserve_fraction >= 0.0 && s.reserve_fraction <= 0.9))
    throw std::invalid_argument("BatteryUseSettings.reserve_fraction = " + std::to_string(s.reserve_fraction) +
                                " is outside [0, 0.9]");
  if (!(s.dt_s > 0.0 && s.dt_s <= 60.0))
    throw std::invalid_argument("BatteryUseSettings.dt_s = " + std::to_string(s.dt_s) + " s is outside (0, 60]");
  double energy_j = 0.0, time_s = 0.0;
  for (const auto& step : profile) {
    energy_j += step.power_w * step.duration_s;
    time_s += step.duration_s;
  }
  BatteryUse u;
  u.mission_energy_j = energy_j;
  u.reserve_pct = 100.0 * s.reserve_fraction;
  const double mean_power = time_s > 0.0 ? energy_j / time_s : 0.0;
  u.usable_energy_j = mean_power > 0.0 ? energy::energyAvailableJ(battery, mean_power, s.dt_s) : 0.0;
  u.margin_j = u.usable_energy_j - u.mission_energy_j;
  u.margin_pct = u.usable_energy_j > 0.0 ? 100.0 * u.margin_j / u.usable_energy_j : 0.0;
  energy::DischargeSettings ds;
  ds.dt_s = s.dt_s;
  ds.keep_series = false;
  const auto r = energy::simulateProfile(battery, profile, ds);
  // Usable charge left on landing as the autopilot counts it: the charge drawn against lambda C0.
  const double left = 1.0 - r.charge_ah / (battery.pack.usable_fraction * battery.capacityAh());
  u.remaining_pct = r.depleted ? 0.0 : 100.0 * std::min(left, 1.0);
  u.depleted = r.depleted;
  u.fits = !r.depleted && left >= s.reserve_fraction;
  if (!u.fits) {
    std::ostringstream w;
    w.precision(3);
    if (r.depleted)
      w << "the mission does NOT fit the battery: it reaches the cut-off after " << r.endurance_s / 60.0 << " of "
        << time_s / 60.0 << " min; split the area or use a larger battery";
    else
      w << "the mission leaves only " << 100.0 * left << " % of the usable charge, less than the "
        << u.reserve_pct << " % reserve";
    u.warning = w.str();
  }
  return u;
}

}  // namespace wattswath::planner
