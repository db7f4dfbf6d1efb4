#pragma once
/// @file battery_use.hpp
/// Predicted battery use of a planned flight: the flight's per-leg powers discharged through the
/// Hwang, Cha & Jung 2018 battery model (Peukert capacity, linear voltage sag; Eq. 9-15).

#include <optional>
#include <string>
#include <vector>

#include "wattswath/energy/battery.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/planner/speed.hpp"

namespace wattswath::planner {

/// Settings of the battery prediction.
struct BatteryUseSettings {
  double reserve_fraction = 0.2;  ///< [-] share of the usable energy to keep in reserve on landing, [0, 0.9]
  double dt_s = 1.0;              ///< [s] discharge time step, (0, 60]
};

/// How a planned flight uses the battery.
struct BatteryUse {
  double usable_energy_j = 0.0;    ///< [J] energy the battery delivers before its cut-off at the flight's mean power
  double mission_energy_j = 0.0;   ///< [J] electrical energy of the flight
  double margin_j = 0.0;           ///< [J] usable minus mission energy (negative: does not fit)
  double margin_pct = 0.0;         ///< [%] margin over usable energy
  double remaining_pct = 0.0;      ///< [%] usable charge left on landing, counted (charge drawn against the usable capacity)
  double reserve_pct = 0.0;        ///< [%] reserve asked for (settings)
  bool fits = false;               ///< true when the flight ends above the cut-off with the reserve left
  bool depleted = false;           ///< true when the cut-off is reached in flight (remaining_pct is then 0)
  std::string warning;             ///< empty when it fits; else a sentence saying why and by how much
};

/// Discharges `battery` along the per-leg powers of `flown` (leg energy over leg time).
/// Throws std::invalid_argument on settings out of range.
BatteryUse predictBatteryUse(const FlownPath& flown, const energy::Battery& battery,
                             const BatteryUseSettings& settings = {});

/// Discharges `battery` along `profile`, a flight's powers from take-off to landing (e.g. the
/// autopilot model's flight of the written mission). The charge left is counted as the autopilot
/// counts it (drawn against the usable capacity); the cut-off follows Hwang's Peukert law.
/// Throws std::invalid_argument on settings out of range.
BatteryUse predictBatteryUse(const std::vector<energy::PowerStep>& profile, const energy::Battery& battery,
                             const BatteryUseSettings& settings = {});

}  // namespace wattswath::planner
