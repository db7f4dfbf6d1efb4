// Returns to launch flown by a real ArduCopter (../shared/data/autopilot-logs/arducopter-3.5_quad_rtl.bin,
// a 3S quad near Utrecht; the log starts as RTL begins and ends on the ground) against the leash
// model flown with the log's own parameters. The figures are in docs/validation.md 5.1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "wattswath/logs/autopilot_log.hpp"
#include "wattswath/logs/dataflash.hpp"
#include "wattswath/logs/parameters.hpp"
#include "wattswath/mission/flight.hpp"

namespace ms = wattswath::mission;
namespace df = wattswath::logs::dataflash;

namespace {

std::string realLog(const std::string& name) { return std::string(WATTSWATH_SHARED_DATA_DIR) + "/autopilot-logs/" + name; }

df::Log readDataflash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return df::Log::parseAcceptingCutEnd(std::move(bytes), path, false);
}

// [s] The first time from 0 on that the horizontal distance of `p(i)` from `home` falls below `radius` [m].
template <class Pos>
double firstWithin(std::size_t n, Pos p, const Eigen::Vector2d& home, double radius) {
  for (std::size_t i = 0; i < n; ++i) {
    const auto [t, xy] = p(i);
    if (t >= 0.0 && (xy - home).norm() < radius) return t;
  }
  return NAN;
}

// [s] The first switch to an RTL mode in `log` and the first event of `end_kind` with text
// `end_text` after it (NaN when missing).
std::pair<double, double> rtlAndEnd(const wattswath::logs::FlightLog& log, const std::string& end_kind, const std::string& end_text) {
  double start = NAN, end = NAN;
  for (const auto& e : log.events) {
    if (e.kind == "mode" && e.text.find("RTL") != std::string::npos && std::isnan(start)) start = e.t;
    if (e.kind == end_kind && e.text == end_text && std::isfinite(start) && std::isnan(end)) end = e.t;
  }
  return {start, end};
}

// The steps of a vehicle hovering at `at` [m from home] (a take-off to its height, then a waypoint
// there with a 1 s hold, reached within `accept_radius_m`, 0: the autopilot's default), then RTL.
std::vector<ms::NavStep> hoverThenReturn(const Eigen::Vector3d& at, double accept_radius_m = 0.0) {
  std::vector<ms::NavStep> steps(3);
  steps[0].kind = ms::NavStep::Kind::Takeoff;
  steps[0].target = {0.0, 0.0, at.z()};
  steps[1].kind = ms::NavStep::Kind::Waypoint;
  steps[1].target = at;
  steps[1].hold_s = 1.0;
  steps[1].accept_radius_m = accept_radius_m;
  steps[2].kind = ms::NavStep::Kind::ReturnToLaunch;
  steps[2].has_position = false;
  return steps;
}

}  // namespace

// The log begins as RTL is entered (MODE RTL, the vehicle hovering 7.2 m above home and 61 m from
// it) and ends with LAND_COMPLETE. The model flies the same return from the same point with the
// log's PARM values: climb to RTL_ALT, the leg home at WPNAV_SPEED, RTL_LOIT_TIME, the land law
// (WPNAV_SPEED_DN above LAND_ALT_LOW, LAND_SPEED below), the throttle's wind-down and the land
// detector. The hover at the start is made by a 1 s hold there (the log's vehicle moves at 0.1 m/s).
// The log carries no version text; its message formats (TimeUS, NKF1, CURR with cell voltages, no
// FMTU) date it between 3.4 and 3.6, which the model flies alike (the leash model with 3.4's
// Pythagorean slack). The vehicle touched down 1.3 m above home by its own altitude estimate (POS
// RelHomeAlt) where the model lands at home's altitude; the log descends a little faster than
// LAND_SPEED below LAND_ALT_LOW, and the two almost cancel (docs/validation.md 5.1).
TEST(RealReturns, ArduCopter35ReturnFrom61MetresOutIsPredictedWithin3Percent) {
  const std::string path = realLog("arducopter-3.5_quad_rtl.bin");
  const auto log = wattswath::logs::readFlightLog(path);
  ASSERT_GE(log.samples.size(), 100u);
  const auto events = rtlAndEnd(log, "event", "EV 18 LAND_COMPLETE");
  const double rtl_start = events.first, land_complete = events.second;
  ASSERT_TRUE(std::isfinite(rtl_start) && std::isfinite(land_complete)) << "RTL mode and LAND_COMPLETE events expected";

  const df::Log bin = readDataflash(path);
  const double start_above_home = bin.column("POS", "RelHomeAlt").front();
  const Eigen::Vector2d start = log.samples.front().position.head<2>();
  const Eigen::Vector2d home = log.samples.back().position.head<2>();  // where it landed: home, as RTL returns there
  EXPECT_NEAR((start - home).norm(), 61.0, 1.0);
  EXPECT_NEAR(start_above_home, 7.2, 0.1);

  const auto params = wattswath::logs::readAutopilotParameters(path);
  EXPECT_TRUE(params.firmware.version.empty()) << "the log was expected to carry no version text";
  ms::AutopilotConfig ap;
  ap.firmware = "ArduCopter";
  ap.version = "3.5";
  ap.family = ms::familyOf(ap.firmware, ap.version);
  ASSERT_EQ(ap.family, ms::AutopilotFamily::ArduCopterLeash);
  ap.parameters = wattswath::logs::flightBehaviourParameters(params);

  const ms::FlownMission f =
      ms::flyMission(hoverThenReturn({start.x() - home.x(), start.y() - home.y(), start_above_home}), ap, ms::FlightSettings{});

  const double t0 = f.events[1].completed_s;
  const double predicted = f.samples.back().t - t0, logged = land_complete - rtl_start;
  const double arrive_pred = firstWithin(
      f.samples.size(), [&](std::size_t i) { return std::make_pair(f.samples[i].t - t0, Eigen::Vector2d(f.samples[i].position.head<2>())); },
      Eigen::Vector2d::Zero(), 2.0);
  const double arrive_log = firstWithin(
      log.samples.size(), [&](std::size_t i) { return std::make_pair(log.samples[i].t - rtl_start, Eigen::Vector2d(log.samples[i].position.head<2>())); },
      home, 2.0);
  std::printf("ArduCopter 3.5 RTL: start to LAND_COMPLETE %.1f s predicted, %.1f s logged (%+.1f %%); within 2 m of home after %.1f s "
              "predicted, %.1f s logged\n",
              predicted, logged, 100.0 * (predicted / logged - 1.0), arrive_pred, arrive_log);
  EXPECT_NEAR(predicted / logged, 1.0, 0.03);
  EXPECT_NEAR(arrive_pred, arrive_log, 1.5);
}

// A return flown by a real PX4 (../shared/data/autopilot-logs/px4-1.9_quad_mission_rtl.ulg: v1.9.0,
// the log starts in a mission). RTL begins 10.0 m above home and 12.9 m from it, with the vehicle
// already heading home at about 4 m/s; it returns at its height (RTL_RETURN_ALT 10 m, no cone in 1.9)
// and lands. The PX4 model, flown with the log's parameters from a hover at the same point, switches
// to the landing within NAV_ACC_RAD (4 m here) of home and closes the rest while descending, as the
// navigator does (with the 0.5 m acceptance it had before 2026-11-27 it predicted 25.1 s, +21 %).
// Version 1.9 predates the trajectory generator the model follows (1.12+), so this checks the
// navigator's return and the landing. The log comes down its last 10 m at 0.67 m/s on average,
// MPC_LAND_SPEED (0.7 m/s): before 1.11 (FlightTaskAutoMapper2) the landing descends at
// MPC_LAND_SPEED everywhere below MPC_LAND_ALT1 (12 m), which the model flies since 2026-11-27
// (19.7 s, -5.0 %); the later law, graded up to 0.9 m/s between MPC_LAND_ALT2 (6 m) and ALT1, gave
// 19.1 s (-7.9 %). What is left is the 2.5 s the log hovers near home turning to the heading home
// was set with (the RTL descend item's yaw, 138 deg away) until within MIS_YAW_ERR (45 deg): the
// model does not turn the heading.
TEST(RealReturns, Px419ReturnAndLandingFrom13MetresOutIsPredictedWithin6Percent) {
  const std::string path = realLog("px4-1.9_quad_mission_rtl.ulg");
  const auto log = wattswath::logs::readFlightLog(path);
  ASSERT_GE(log.samples.size(), 20u);
  const auto events = rtlAndEnd(log, "landed", "landed");
  const double rtl_start = events.first, landed = events.second;
  ASSERT_TRUE(std::isfinite(rtl_start) && std::isfinite(landed)) << "AUTO_RTL and landed events expected";
  // The vehicle's position at the switch to RTL (interpolated between samples) and home, where it landed.
  Eigen::Vector3d start = log.samples.front().position;
  for (std::size_t i = 1; i < log.samples.size(); ++i) {
    const auto &a = log.samples[i - 1], &b = log.samples[i];
    if (a.t <= rtl_start && b.t >= rtl_start) {
      start = a.position + (b.position - a.position) * ((rtl_start - a.t) / std::max(b.t - a.t, 1e-9));
      break;
    }
  }
  const Eigen::Vector3d home = log.samples.back().position;
  const Eigen::Vector3d rel = start - home;
  EXPECT_NEAR(rel.head<2>().norm(), 12.9, 0.3);
  EXPECT_NEAR(rel.z(), 10.0, 0.3);

  const auto params = wattswath::logs::readAutopilotParameters(path);
  ms::AutopilotConfig ap;
  ap.firmware = "PX4";
  ap.version = params.firmware.version;
  ap.family = ms::familyOf(ap.firmware, ap.version);
  ap.parameters = wattswath::logs::flightBehaviourParameters(params);
  EXPECT_EQ(ap.get("NAV_ACC_RAD"), 4.0);

  const ms::FlownMission f = ms::flyMission(hoverThenReturn(rel, 0.5), ap, ms::FlightSettings{});
  const double predicted = f.samples.back().t - f.events[1].completed_s, logged = landed - rtl_start;
  std::printf("PX4 1.9 RTL: start to landed %.1f s predicted, %.1f s logged (%+.1f %%)\n", predicted, logged,
              100.0 * (predicted / logged - 1.0));
  EXPECT_NEAR(predicted / logged, 1.0, 0.06);
}
