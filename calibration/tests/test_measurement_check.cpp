// The measurement check of issue 19: a simulated flight of the vehicle passes; current stuck at
// 0 A, a constant current, a power far below or above the physics hover power are refused with the
// current and what was seen named; a diverged position estimate is cut off (late) or refused (early).
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.hpp"
#include "wattswath/calibration/diagnose.hpp"
#include "wattswath/calibration/measurement_check.hpp"

using namespace wattswath::energy;
using namespace wattswath::logs;
using namespace wattswath::calibration;

namespace {

Vehicle iris() { return loadVehicle(wattswath::test::sourcePath("data/vehicles/iris.json")); }

// The paper model flown along a short survey with a take-off and a landing, 5 Hz.
FlightLog flight() {
  const Vehicle v = iris();
  SimulationSettings s;
  s.rate_hz = 5.0;
  return simulateFlight({{0, 0, 0}, {0, 0, 10}, {60, 0, 10}, {60, 20, 10}, {0, 20, 10}, {0, 20, 0}},
                        buildModel(v, {"hover", "kinetic", "parasitic_drag"}), s);
}

// Current (and power) of every sample scaled by `k`.
FlightLog scaled(double k) {
  FlightLog log = flight();
  for (auto& x : log.samples) {
    x.current *= k;
    x.power *= k;
  }
  return log;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(MeasurementCheck, SimulatedFlightOfTheVehicleIsPlausible) {
  FlightLog log = flight();
  const size_t n = log.samples.size();
  const auto c = checkMeasurement(log, iris());
  EXPECT_TRUE(c.power_problem.empty()) << c.power_problem;
  EXPECT_TRUE(c.position_problem.empty()) << c.position_problem;
  EXPECT_FALSE(c.cut);
  EXPECT_EQ(log.samples.size(), n);
  EXPECT_NEAR(c.hover_power_w, marinsHoverPowerW(iris()), 1e-9);
  EXPECT_GT(c.airborne_samples, 0);
  EXPECT_NEAR(c.median_power_w / c.hover_power_w, 1.0, 0.3);
}

// A voltage logged in millivolts read as a power a thousand times hover's and was blamed on the
// current sensor; it is now named, with the likely unit. Another battery (4S for a 3S vehicle
// file) is a note only: the power is measured either way.
TEST(MeasurementCheck, AVoltageInMillivoltsIsNamedNotTheCurrent) {
  FlightLog log = flight();
  for (auto& x : log.samples) {
    x.voltage *= 1000.0;
    x.power *= 1000.0;
  }
  const auto c = checkMeasurement(log, iris());
  EXPECT_TRUE(contains(c.power_problem, "battery voltage while airborne")) << c.power_problem;
  EXPECT_TRUE(contains(c.power_problem, "logged in millivolts?")) << c.power_problem;
  EXPECT_FALSE(contains(c.power_problem, "current sensor")) << c.power_problem;
  FlightLog four = flight();
  for (auto& x : four.samples) {
    x.voltage *= 4.0 / 3.0 * 1.5;  // 2x: another pack, not another unit
    x.power *= 4.0 / 3.0 * 1.5;
    x.current /= 4.0 / 3.0 * 1.5;
    x.power /= 4.0 / 3.0 * 1.5;
  }
  const auto n = checkMeasurement(four, iris());
  EXPECT_TRUE(n.power_problem.empty()) << n.power_problem;
  ASSERT_FALSE(n.notes.empty());
  EXPECT_TRUE(contains(n.notes.back(), "not that of the vehicle file's battery")) << n.notes.back();
}

TEST(MeasurementCheck, CurrentStuckAtZeroIsRefusedNamingTheCurrent) {
  FlightLog log = scaled(0.0);
  const auto c = checkMeasurement(log, iris());
  EXPECT_TRUE(contains(c.power_problem, "battery current reads 0 A in all")) << c.power_problem;
  EXPECT_TRUE(contains(c.power_problem, "airborne samples")) << c.power_problem;
}

// A battery without a current sensor: ArduPilot logs BAT.Curr as NaN, PX4 current_a as -1 (read as
// NaN). The check passed it (median power NaN) and replay, fit and diagnose then died on "sample 0
// has no power"; now the current is said not to be measured, in how many samples.
TEST(MeasurementCheck, ACurrentThatIsNotMeasuredIsSaidToBe) {
  FlightLog log = flight();
  for (size_t i = 0; i < log.samples.size(); i += 2) {
    log.samples[i].current = std::nan("");
    log.samples[i].power = std::nan("");
  }
  const auto c = checkMeasurement(log, iris());
  EXPECT_TRUE(contains(c.power_problem, "the battery current is not measured in ")) << c.power_problem;
  EXPECT_TRUE(contains(c.power_problem, "ArduPilot logs BAT.Curr as NaN")) << c.power_problem;
}

// A log whose position and velocity are exactly still while the current says it flies (all zero:
// no position, or a ground run at 8 A) was replayed (+119 %), fitted and diagnosed "nothing missing".
TEST(MeasurementCheck, ExactlyStillKinematicsAreNoFlight) {
  FlightLog log = flight();
  for (auto& x : log.samples) {
    x.position.setZero();
    x.velocity.setZero();
    x.acceleration.setZero();
  }
  const auto c = checkMeasurement(log, iris());
  EXPECT_TRUE(contains(c.position_problem, "do not change at all over the")) << c.position_problem;
  // A real hover jitters: a centimetre of it is a flight.
  FlightLog hover = log;
  for (size_t i = 0; i < hover.samples.size(); ++i) hover.samples[i].position.z() = 10.0 + 0.01 * std::sin(0.7 * i);
  EXPECT_TRUE(checkMeasurement(hover, iris()).position_problem.empty());
}

TEST(MeasurementCheck, NineWattsForAFlyingQuadIsFarBelowHover) {
  FlightLog log = scaled(9.0 / marinsHoverPowerW(iris()));
  const auto c = checkMeasurement(log, iris());
  EXPECT_TRUE(contains(c.power_problem, "far below hover")) << c.power_problem;
  EXPECT_TRUE(contains(c.power_problem, "battery current median")) << c.power_problem;
  EXPECT_TRUE(contains(c.power_problem, "expected at least 0.25 x")) << c.power_problem;
  EXPECT_NEAR(c.median_power_w, 9.0, 2.0);
}

TEST(MeasurementCheck, TheBandIsGenerous) {
  for (double k : {0.3, 0.5, 2.0, 5.0}) {
    FlightLog log = scaled(k);
    EXPECT_TRUE(checkMeasurement(log, iris()).power_problem.empty()) << "x" << k;
  }
  FlightLog high = scaled(9.0);
  EXPECT_TRUE(contains(checkMeasurement(high, iris()).power_problem, "far above hover"));
}

TEST(MeasurementCheck, ConstantCurrentIsNotAMeasurement) {
  FlightLog log = flight();
  for (auto& x : log.samples) {
    x.current = 17.5;
    x.power = x.voltage * x.current;
  }
  const auto c = checkMeasurement(log, iris());
  EXPECT_TRUE(contains(c.power_problem, "battery current is constant at 17.5 A")) << c.power_problem;
}

TEST(MeasurementCheck, PowerOnlyLogStuckAtZeroIsRefused) {
  FlightLog log = flight();
  for (auto& x : log.samples) x.voltage = x.current = std::nan(""), x.power = 0.0;
  EXPECT_TRUE(contains(checkMeasurement(log, iris()).power_problem, "measured power is constant at 0 W"));
}

TEST(MeasurementCheck, LateDivergenceIsCutWithTheReason) {
  FlightLog log = flight();
  const size_t n = log.samples.size();
  const double t_bad = log.samples[n * 3 / 4].t;
  for (size_t i = n * 3 / 4; i < n; ++i) log.samples[i].velocity.z() = 120.0;
  log.airborne = {{0.0, log.samples.back().t}};
  const auto c = checkMeasurement(log, iris());
  EXPECT_TRUE(c.position_problem.empty()) << c.position_problem;
  ASSERT_TRUE(c.cut);
  EXPECT_DOUBLE_EQ(c.cut_at_s, t_bad);
  EXPECT_EQ(log.samples.size(), n * 3 / 4);
  ASSERT_EQ(log.airborne.size(), 1u);
  EXPECT_DOUBLE_EQ(log.airborne[0].end, log.samples.back().t);
  ASSERT_EQ(c.notes.size(), 1u);
  EXPECT_TRUE(contains(c.notes[0], "vertical speed 120 m/s, expected at most 15 m/s")) << c.notes[0];
  EXPECT_TRUE(contains(c.notes[0], "are not used")) << c.notes[0];
  EXPECT_TRUE(contains(log.metadata["warnings"], "EKF diverged"));
  EXPECT_TRUE(c.power_problem.empty()) << c.power_problem;
}

TEST(MeasurementCheck, EarlyDivergenceIsRefused) {
  FlightLog log = flight();
  for (size_t i = 5; i < log.samples.size(); ++i) log.samples[i].position.z() = i % 2 ? -1629.0 : 2176.0;
  const auto c = checkMeasurement(log, iris());
  EXPECT_TRUE(contains(c.position_problem, "altitude")) << c.position_problem;
  EXPECT_TRUE(contains(c.position_problem, "cannot be used")) << c.position_problem;
}

TEST(MeasurementCheck, HorizontalLimitFollowsTheVehicle) {
  FlightLog log = flight();
  for (size_t i = log.samples.size() / 2; i < log.samples.size(); ++i) log.samples[i].velocity.x() = 45.0;
  Vehicle fast = iris();
  fast.max_speed_mps = 30.0;  // 2 x 30 = 60 m/s allowed
  FlightLog copy = log;
  EXPECT_FALSE(checkMeasurement(copy, fast).cut);
  EXPECT_TRUE(checkMeasurement(log, iris()).cut);
}

TEST(MeasurementCheck, LimitsAreValidated) {
  MeasurementLimits l;
  l.min_hover_fraction = 2.0;
  EXPECT_THROW(validate(l), std::invalid_argument);
}

}  // namespace
