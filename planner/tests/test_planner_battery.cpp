// Predicted battery use of a plan (Hwang et al. 2018 discharge of the per-leg powers).
#include <gtest/gtest.h>

#include "wattswath/energy/battery.hpp"
#include "wattswath/planner/battery_use.hpp"

using namespace wattswath;

namespace {

// Hwang Table 1 pack, 2S (the hexacopter of data/vehicles/hwang-hexacopter.json).
energy::Battery hwang2S() {
  energy::BatteryPack p;
  p.capacity_ah = 16.0;
  p.rated_discharge_time_s = 720.0;
  p.voltage_full_v = 24.5;
  p.voltage_standard_v = 22.2;
  p.mass_kg = 2.0;
  p.usable_fraction = 0.7;
  p.peukert_exponent = 1.05;
  return energy::makeBattery(p, 2, 1);
}

// A flight of `legs` legs of `seconds` each at constant `power` [W].
planner::FlownPath flight(int legs, double seconds, double power) {
  planner::FlownPath f;
  for (int i = 0; i < legs; ++i) {
    f.leg_time.push_back(seconds);
    f.leg_energy.push_back(power * seconds);
  }
  f.time = legs * seconds;
  f.energy = power * f.time;
  return f;
}

}  // namespace

TEST(PlannerBattery, ShortFlightFitsWithMargin) {
  const auto b = hwang2S();
  const auto u = planner::predictBatteryUse(flight(10, 30.0, 2000.0), b);  // 5 min at 2 kW
  EXPECT_TRUE(u.fits) << u.warning;
  EXPECT_TRUE(u.warning.empty());
  EXPECT_NEAR(u.usable_energy_j, energy::energyAvailableJ(b, 2000.0), 1e-6);
  EXPECT_NEAR(u.margin_j, u.usable_energy_j - 2000.0 * 300.0, 1e-6);
  EXPECT_GT(u.remaining_pct, 20.0);
  EXPECT_LT(u.remaining_pct, 100.0);
}

TEST(PlannerBattery, LongFlightDoesNotFitAndSaysSo) {
  const auto b = hwang2S();
  const double endurance = energy::endurance(b, 2000.0).endurance_s;
  const auto u = planner::predictBatteryUse(flight(20, 0.1 * endurance, 2000.0), b);  // twice the endurance
  EXPECT_FALSE(u.fits);
  EXPECT_LT(u.margin_j, 0.0);
  EXPECT_EQ(u.remaining_pct, 0.0);
  EXPECT_NE(u.warning.find("does NOT fit"), std::string::npos) << u.warning;
}

TEST(PlannerBattery, BelowReserveWarns) {
  const auto b = hwang2S();
  const double endurance = energy::endurance(b, 2000.0).endurance_s;
  const auto u = planner::predictBatteryUse(flight(10, 0.09 * endurance, 2000.0), b);  // 90 % of it
  EXPECT_FALSE(u.fits);
  EXPECT_GT(u.remaining_pct, 0.0);
  EXPECT_NE(u.warning.find("reserve"), std::string::npos) << u.warning;
  EXPECT_THROW(planner::predictBatteryUse(flight(1, 1, 1), b, {1.5, 1.0}), std::invalid_argument);
}
