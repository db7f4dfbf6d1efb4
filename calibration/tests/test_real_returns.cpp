// A return to launch flown by a real ArduCopter (../shared/data/autopilot-logs/arducopter-3.5_quad_rtl.bin,
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
  double rtl_start = NAN, land_complete = NAN;
  for (const auto& e : log.events) {
    if (e.kind == "mode" && e.text.find("RTL") != std::string::npos && std::isnan(rtl_start)) rtl_start = e.t;
    if (e.kind == "event" && e.text == "EV 18 LAND_COMPLETE" && std::isnan(land_complete)) land_complete = e.t;
  }
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

  std::vector<ms::NavStep> steps(3);
  steps[0].kind = ms::NavStep::Kind::Takeoff;
  steps[0].target = {0.0, 0.0, start_above_home};
  steps[1].kind = ms::NavStep::Kind::Waypoint;
  steps[1].target = {start.x() - home.x(), start.y() - home.y(), start_above_home};
  steps[1].hold_s = 1.0;
  steps[2].kind = ms::NavStep::Kind::ReturnToLaunch;
  steps[2].has_position = false;
  const ms::FlownMission f = ms::flyMission(steps, ap, ms::FlightSettings{});

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
