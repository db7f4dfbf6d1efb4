// Hwang, Cha & Jung 2018: battery discharge (Eq. 9-15), forward flight (Eq. 1-8), the vehicle
// file's extension, limits, monotonicity, convergence and clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>

#include "test_util.hpp"
#include "wattswath/energy/battery.hpp"
#include "wattswath/energy/forward_flight.hpp"

using namespace wattswath::energy;

namespace {

BatteryPack tattu() {  // Hwang Table 1
  return loadVehicle(wattswath::test::sourcePath("data/vehicles/hwang-hexacopter.json")).battery->pack;
}

Vehicle hexacopter() { return loadVehicle(wattswath::test::sourcePath("data/vehicles/hwang-hexacopter.json")); }

// Hover rotor power of the paper's hexacopter at total mass m (diameter reading), over eta.
double hoverElectricW(double mass_kg, double eta) {
  const double t = mass_kg * 9.81, a = 6.0 * M_PI * 0.2794 * 0.2794;
  return std::pow(t, 1.5) / std::sqrt(2.0 * 1.225 * a) / eta;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// ---------------------------------------------------------------- battery
TEST(Battery, SeriesAndParallelScaleVoltageCapacityAndMass) {
  const Battery b = makeBattery(tattu(), 2, 3);
  EXPECT_DOUBLE_EQ(b.voltageFull(), 49.0);
  EXPECT_DOUBLE_EQ(b.capacityAh(), 48.0);
  EXPECT_DOUBLE_EQ(b.mass(), 12.0);
  EXPECT_EQ(parseBatteryConfiguration("2S2P"), std::make_pair(2, 2));
  EXPECT_EQ(parseBatteryConfiguration("3p"), std::make_pair(1, 3));
  EXPECT_NE(errorOf([] { parseBatteryConfiguration("2X"); }).find("'2X'"), std::string::npos);
}

TEST(Battery, PeukertCapacityIsNominalAtRatedCurrentAndFallsWithCurrent) {
  const Battery b = makeBattery(tattu(), 2, 1);
  const double rated = 16.0 / 0.2;  // C0 / t0 [A]
  EXPECT_NEAR(peukertCapacityAh(b, rated), 16.0, 1e-12);
  EXPECT_GT(peukertCapacityAh(b, 0.5 * rated), 16.0);
  EXPECT_LT(peukertCapacityAh(b, 2.0 * rated), 16.0);
  BatteryPack ideal = tattu();
  ideal.peukert_exponent = 1.0;
  EXPECT_NEAR(peukertCapacityAh(makeBattery(ideal, 1, 1), 3.0), 16.0, 1e-12);
}

TEST(Battery, VoltageFallsLinearlyFromFullToStandardOverLambda) {
  const Battery b = makeBattery(tattu(), 2, 1);
  EXPECT_DOUBLE_EQ(voltageAt(b, 16.0), 49.0);
  EXPECT_NEAR(voltageAt(b, cutoffResidualAh(b)), 44.4, 1e-12);
  EXPECT_NEAR(cutoffResidualAh(b), 0.3 * 16.0, 1e-12);
}

TEST(Battery, IdealBatteryEnduranceHasClosedForm) {
  // P = 1: no Peukert effect; V(q) = V0 - k q over drawn charge q; dq/dt = P / V(q) gives
  // t = (V0 q - k q^2 / 2) / P for q = lambda C0, i.e. lambda C0 (V0 + Vs) / 2 / P.
  BatteryPack p = tattu();
  p.peukert_exponent = 1.0;
  const Battery b = makeBattery(p, 2, 1);
  const double power = 1500.0;
  const double expected = 0.7 * 16.0 * 3600.0 * (49.0 + 44.4) / 2.0 / power;
  EXPECT_NEAR(endurance(b, power, 0.01).endurance_s, expected, 1e-3 * expected);
  EXPECT_NEAR(energyAvailableJ(b, power, 0.01), 0.7 * 16.0 * 3600.0 * (49.0 + 44.4) / 2.0, 2e-3 * expected * power);
}

TEST(Battery, StepSizeDoesNotMatter) {
  const Battery b = makeBattery(tattu(), 2, 2);
  const double fine = endurance(b, 2200.0, 0.05).endurance_s;
  for (double dt : {0.5, 1.0, 5.0, 30.0}) {
    EXPECT_NEAR(endurance(b, 2200.0, dt).endurance_s, fine, 1e-3 * fine) << "dt " << dt;
  }
  // First-order convergence: halving the step roughly halves the error.
  const double e1 = std::abs(endurance(b, 2200.0, 20.0).endurance_s - fine);
  const double e2 = std::abs(endurance(b, 2200.0, 10.0).endurance_s - fine);
  EXPECT_LT(e2, 0.7 * e1 + 1e-6);
}

TEST(Battery, EnduranceFallsWithPowerAndRisesWithPacks) {
  const Battery b2 = makeBattery(tattu(), 2, 1), b4 = makeBattery(tattu(), 2, 2);
  double prev = 1e30;
  for (double p = 200.0; p <= 5000.0; p += 400.0) {
    const double t = endurance(b2, p).endurance_s;
    EXPECT_LT(t, prev);
    prev = t;
    EXPECT_GT(endurance(b4, p).endurance_s, 2.0 * t);  // Peukert: half the current per pack lasts longer
  }
}

TEST(Battery, TimeSeriesEndsAtCutoffWithFallingVoltageAndRisingCurrent) {
  const Battery b = makeBattery(tattu(), 2, 1);
  const auto r = endurance(b, 1500.0, 1.0);
  ASSERT_TRUE(r.depleted);
  ASSERT_GT(r.series.size(), 100u);
  EXPECT_DOUBLE_EQ(r.series.front().voltage_v, 49.0);
  EXPECT_NEAR(r.series.back().residual_ah, cutoffResidualAh(b), 1e-12);
  EXPECT_NEAR(r.series.back().usable_left, 0.0, 1e-12);
  // From the second step on (the first step already counts Peukert's effective capacity, above C0
  // at this current, so Eq. 11 lifts the voltage slightly above V0 once: the paper's formulation).
  for (size_t k = 3; k < r.series.size(); ++k) {
    EXPECT_LE(r.series[k].voltage_v, r.series[k - 1].voltage_v + 1e-12);
    EXPECT_GE(r.series[k].current_a, r.series[k - 1].current_a - 1e-12);
  }
  EXPECT_NEAR(r.energy_j, 1500.0 * r.endurance_s, 1e-6 * r.energy_j);
}

TEST(Battery, ProfileEqualsConstantPowerAndStopsAtDepletion) {
  const Battery b = makeBattery(tattu(), 2, 1);
  const auto constant = endurance(b, 1500.0, 1.0);
  const auto split = simulateProfile(b, {{600.0, 1500.0}, {600.0, 1500.0}, {1e5, 1500.0}});
  EXPECT_NEAR(split.endurance_s, constant.endurance_s, 1e-9);
  EXPECT_TRUE(split.depleted);
  // A short mission leaves charge: not depleted, residual above the cut-off.
  const auto mission = simulateProfile(b, {{300.0, 1500.0}, {60.0, 0.0}, {300.0, 2000.0}});
  EXPECT_FALSE(mission.depleted);
  EXPECT_NEAR(mission.endurance_s, 660.0, 1e-9);
  EXPECT_GT(mission.final_residual_ah, cutoffResidualAh(b));
  EXPECT_NEAR(mission.energy_j, 300.0 * 1500.0 + 300.0 * 2000.0, 1e-6);
}

TEST(Battery, BadParametersGiveClearErrors) {
  BatteryPack p = tattu();
  p.voltage_standard_v = 30.0;
  EXPECT_NE(errorOf([&] { makeBattery(p, 1, 1); }).find("battery.voltage_standard_v"), std::string::npos);
  p = tattu();
  p.usable_fraction = 1.5;
  EXPECT_NE(errorOf([&] { makeBattery(p, 1, 1); }).find("battery.usable_fraction' = 1.5"), std::string::npos);
  EXPECT_NE(errorOf([&] { makeBattery(tattu(), 0, 1); }).find("battery.series"), std::string::npos);
  const Battery b = makeBattery(tattu(), 2, 1);
  EXPECT_NE(errorOf([&] { endurance(b, -5.0); }).find("power = -5"), std::string::npos);
  EXPECT_NE(errorOf([&] { endurance(b, 1000.0, 0.0); }).find("dt = 0"), std::string::npos);
  EXPECT_NE(errorOf([&] { simulateProfile(b, {{-1.0, 10.0}}); }).find("step 0 duration"), std::string::npos);
}

// ---------------------------------------------------------------- Eq. 5
TEST(InducedVelocity, HoverIsSqrtOfThrustOver2RhoA) {
  EXPECT_NEAR(inducedVelocity(137.34, 0.0, 0.0, 1.225, 1.4715), std::sqrt(137.34 / (2 * 1.225 * 1.4715)), 1e-12);
  EXPECT_EQ(inducedVelocity(0.0, 5.0, 0.1, 1.225, 1.0), 0.0);
}

TEST(InducedVelocity, SatisfiesEq5AndTendsToAsymptoteAtHighSpeed) {
  const double t = 150.0, rho = 1.225, a = 1.4715, c = t / (2 * rho * a);
  for (double u = 0.01; u <= 30.0; u *= 1.3) {
    for (double th : {0.0, 0.2, 0.6, 1.2}) {
      const double ui = inducedVelocity(t, u, th, rho, a);
      const double rhs = c / std::hypot(u * std::cos(th), u * std::sin(th) + ui);
      EXPECT_NEAR(ui, rhs, 1e-12 * std::max(1.0, ui)) << "U " << u << " theta " << th;
    }
  }
  const double ui30 = inducedVelocity(t, 30.0, 0.0, rho, a);
  EXPECT_NEAR(ui30 / (c / 30.0), 1.0, 0.01);  // T/(2 rho A U), within 1 % at 30 m/s
  EXPECT_LT(ui30, c / 30.0);
}

TEST(InducedVelocity, FallsMonotonicallyWithSpeedFromHoverTo30) {
  double prev = inducedVelocity(150.0, 0.0, 0.0, 1.225, 1.4715);
  for (double u = 0.05; u <= 30.0; u += 0.05) {
    const double ui = inducedVelocity(150.0, u, 0.1, 1.225, 1.4715);
    EXPECT_LT(ui, prev) << u;
    prev = ui;
  }
}

TEST(InducedVelocity, RejectsBadInput) {
  EXPECT_THROW(inducedVelocity(-1.0, 1.0, 0.0, 1.225, 1.0), std::invalid_argument);
  EXPECT_THROW(inducedVelocity(1.0, 1.0, 2.0, 1.225, 1.0), std::invalid_argument);
  EXPECT_THROW(inducedVelocity(1.0, NAN, 0.0, 1.225, 1.0), std::invalid_argument);
}

// ---------------------------------------------------------------- Eq. 1-8
TEST(ForwardFlight, HoverPowerIsMomentumTheoryOverEfficiency) {
  const auto p = forwardFlightParameters(hexacopter());
  const auto s = forwardFlight(p, 0.0);
  EXPECT_NEAR(s.thrust_n, 14.0 * 9.81, 1e-9);
  EXPECT_EQ(s.tilt_rad, 0.0);
  EXPECT_NEAR(s.electrical_power_w, hoverElectricW(14.0, 0.571), 1e-6);
}

TEST(ForwardFlight, ThrustTiltAndPowerFollowEq1To4) {
  const auto p = forwardFlightParameters(hexacopter());
  const auto s = forwardFlight(p, 12.0);
  const double d = 0.5 * 1.225 * 0.67 * 144.0;
  EXPECT_NEAR(s.drag_n, d, 1e-9);
  EXPECT_NEAR(s.thrust_n, std::hypot(14.0 * 9.81, d), 1e-9);
  EXPECT_NEAR(std::tan(s.tilt_rad), d / (14.0 * 9.81), 1e-12);
  EXPECT_NEAR(s.rotor_power_w, s.thrust_n * s.induced_velocity_mps + d * 12.0, 1e-9);
  // The forward-flight effects sum to the same power.
  const EnergyModel m = hwangModel(hexacopter());
  EXPECT_NEAR(m.levelPower(12.0, 0.7), s.electrical_power_w, 1e-9);
}

TEST(ForwardFlight, WithoutDragPowerFallsMonotonicallyWithSpeed) {
  auto p = forwardFlightParameters(hexacopter());
  p.drag_area_m2 = 0.0;
  double prev = forwardFlight(p, 0.0).electrical_power_w;
  for (double u = 0.5; u <= 30.0; u += 0.5) {
    const double pw = forwardFlight(p, u).electrical_power_w;
    EXPECT_LT(pw, prev);
    prev = pw;
  }
}

TEST(ForwardFlight, EfficiencyTableIsInterpolatedMonotonically) {
  // A synthetic manufacturer table: per-rotor input power 1.8 x ideal at each thrust.
  const double a = 1.4715, rho = 1.225;
  std::vector<double> t = {10, 15, 20, 25, 30, 35, 40, 45, 50}, pw;
  for (double x : t) pw.push_back(1.8 * std::pow(6 * x, 1.5) / std::sqrt(2 * rho * a) / 6.0);
  const auto eta = EfficiencyCurve::fromThrustPowerTable(t, pw, 6, a, rho);
  EXPECT_FALSE(eta.isConstant());
  for (double x : t) EXPECT_NEAR(eta(6.0 * x), 1.0 / 1.8, 1e-12) << x;         // exact at the nodes
  for (double x = 60.0; x <= 300.0; x += 7.0) EXPECT_NEAR(eta(x), 1.0 / 1.8, 0.01) << x;  // spline between
  EXPECT_FALSE(eta.inTableRange(400.0));
  EXPECT_NEAR(eta(1000.0), eta(300.0), 1e-12);  // held at the end value outside the table
  EXPECT_NEAR(eta.scaled(0.5)(120.0), 0.5 * eta(120.0), 1e-12);
}

TEST(ForwardFlight, BadEfficiencyTablesGiveClearErrors) {
  const auto err = [](std::vector<double> t, std::vector<double> p) {
    return errorOf([&] { EfficiencyCurve::fromThrustPowerTable(t, p, 6, 1.47, 1.225); });
  };
  EXPECT_NE(err({1, 2, 3}, {1, 2, 3}).find("at least 4"), std::string::npos);
  EXPECT_NE(err({1, 2, 3, 4}, {1, 2, 3}).find("equal lengths"), std::string::npos);
  EXPECT_NE(err({1, 3, 2, 4}, {100, 200, 300, 400}).find("row 2"), std::string::npos);
  EXPECT_NE(err({10, 20, 30, 40}, {1, 2, 3, 4}).find("eta ="), std::string::npos);
  EXPECT_NE(errorOf([] { EfficiencyCurve::constant(1.2); }).find("(0, 1]"), std::string::npos);
}

TEST(ForwardFlight, VehicleExtensionIsValidated) {
  std::string text;
  {
    std::ifstream in(wattswath::test::sourcePath("data/vehicles/hwang-hexacopter.json"));
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    t.replace(t.find(from), from.size(), to);
    return errorOf([&] { forwardFlightParameters(parseVehicle(t, "h.json")); });
  };
  EXPECT_NE(with("\"efficiency\": 0.571", "\"efficiency\": 1.7").find("extensions.hwang.efficiency"), std::string::npos);
  EXPECT_NE(with("\"efficiency\": 0.571", "\"efficency\": 0.571").find("unknown field 'extensions.hwang.efficency'"),
            std::string::npos);
  EXPECT_NE(with("\"efficiency\": 0.571", "\"thrust_power_table\": {\"thrust_n\": [1,2,3,4], \"power_w\": [1,2,3]}")
                .find("extensions.hwang.thrust_power_table"),
            std::string::npos);
  EXPECT_NE(with("\"extensions\": {", "\"extensions\": 5, \"x\": {").find("extensions"), std::string::npos);
  EXPECT_THROW(forwardFlightParameters(hexacopter(), -1.0), std::invalid_argument);
}

TEST(ForwardFlight, VehicleRoundTripsWithExtensions) {
  const Vehicle v = hexacopter();
  const Vehicle w = parseVehicle(vehicleToJson(v), "rt");
  EXPECT_EQ(w.extensions.at("hwang"), v.extensions.at("hwang"));
  EXPECT_EQ(hwangExtension(w).battery_configurations.size(), 3u);
}

TEST(ForwardFlight, BatteryConfigurationsOfTable3) {
  const Vehicle v = hexacopter();
  const Vehicle v4 = withBatteryConfiguration(v, 2, 2), v6 = withBatteryConfiguration(v, 2, 3);
  EXPECT_DOUBLE_EQ(v4.mass_kg, 18.0);
  EXPECT_DOUBLE_EQ(v6.mass_kg, 22.0);
  EXPECT_DOUBLE_EQ(v6.battery->capacityAh(), 48.0);
  EXPECT_DOUBLE_EQ(v6.battery->voltageFull(), 49.0);
}

// ---------------------------------------------------------------- reproduction checks
TEST(Table3, ConstantEfficiency0563ReproducesThePapersHoverEstimates) {
  // Paper: 22.24, 31.21, 34.91 min. One constant eta = 0.563 (diameter reading) gives all three
  // within 0.1 %: this checks the battery loop (Eq. 13-15) against the paper's.
  const Battery b = *hexacopter().battery;
  const double paper[3] = {22.24, 31.21, 34.91};
  const double mass[3] = {14.0, 18.0, 22.0};
  for (int k = 0; k < 3; ++k) {
    const Battery bk = makeBattery(b.pack, 2, k + 1);
    const double ours = endurance(bk, hoverElectricW(mass[k], 0.563), 0.5).endurance_s / 60.0;
    EXPECT_NEAR(ours, paper[k], 1e-3 * paper[k]) << "row " << k;
  }
}

TEST(Figure8, FullPayloadHoverEndurance) {
  // Paper: W_p/W_v = 1 gives 9.3 min against 22.2 min empty (hover, 2 packs in series).
  const Battery b = *hexacopter().battery;
  EXPECT_NEAR(endurance(b, hoverElectricW(24.0, 0.563)).endurance_s / 60.0, 9.3, 0.05);
  EXPECT_NEAR(endurance(b, hoverElectricW(14.0, 0.563)).endurance_s / 60.0, 22.2, 0.05);
}

namespace {
double bestSpeed(const ForwardFlightParameters& p) {
  double best = 0.0, pmin = 1e30;
  for (double u = 0.0; u <= 25.0; u += 0.05) {
    const double pw = forwardFlight(p, u).electrical_power_w;
    if (pw < pmin) pmin = pw, best = u;
  }
  return best;
}
}  // namespace

TEST(Figure6, OptimumSpeedFallsAsDragCoefficientRises) {
  // Table 2's drag coefficients on the frontal area S = 0.827 m^2, W = 14 kg.
  auto p = forwardFlightParameters(hexacopter());
  double prev = 1e30;
  for (double cd : {0.4, 0.96, 1.05, 1.4}) {
    p.drag_area_m2 = 0.827 * cd;
    const double u = bestSpeed(p);
    EXPECT_LT(u, prev) << "Cd " << cd;
    EXPECT_GT(u, 1.0);
    prev = u;
  }
  p.drag_area_m2 = 0.827 * 0.004;  // dolphin: power still falling at 20 m/s
  EXPECT_GT(bestSpeed(p), 20.0);
}

TEST(Figure8, OptimumSpeedRisesWithPayload) {
  auto p = forwardFlightParameters(hexacopter());
  p.drag_area_m2 = 0.827 * 0.96;
  double prev = 0.0;
  for (double ratio = 0.0; ratio <= 1.0; ratio += 0.25) {
    p.mass_kg = 14.0 + ratio * 10.0;
    const double u = bestSpeed(p);
    EXPECT_GT(u, prev) << "W_p/W_v " << ratio;
    prev = u;
  }
}
