// NAV_SPLINE_WAYPOINT as ArduCopter 4.x flies it (AP_Math/SplineCurve.cpp, AC_WPNav): between two
// stops a spline is the straight line flown at half the acceleration limit; through spline
// waypoints the path is the Hermite curve, taken within half the acceleration limit sideways; a
// straight leg and a spline meet at a speed, on the waypoint, without a stop or a cut corner.
#include <gtest/gtest.h>

#include <cmath>

#include "flight_test_util.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/flight.hpp"

using namespace wattswath::mission;
using wattswath::mission::testing::localMission;
using wattswath::mission::testing::minSpeedBetween;

namespace {

// The autopilot's target alone (the vehicle on it), for hand-worked paths and speeds.
FlightSettings onTarget() {
  FlightSettings s;
  s.airframe.track = false;
  return s;
}

// [m] How close the flight passes `p`.
double closestTo(const FlownMission& f, const Eigen::Vector3d& p) {
  double d = 1e9;
  for (const auto& s : f.samples) d = std::min(d, (s.position - p).norm());
  return d;
}

// [m/s^2] The largest acceleration across the direction of travel between `t0` and `t1` [s], from
// the samples' velocities (central differences).
double largestLateralAcceleration(const FlownMission& f, double t0, double t1) {
  double a_max = 0.0;
  for (std::size_t i = 1; i + 1 < f.samples.size(); ++i) {
    const auto& s = f.samples[i];
    if (s.t < t0 || s.t > t1 || s.velocity.norm() < 0.5) continue;
    const Eigen::Vector3d a = (f.samples[i + 1].velocity - f.samples[i - 1].velocity) / (f.samples[i + 1].t - f.samples[i - 1].t);
    const Eigen::Vector3d u = s.velocity.normalized();
    a_max = std::max(a_max, (a - a.dot(u) * u).norm());
  }
  return a_max;
}

}  // namespace

TEST(ArduCopterSpline, BetweenTwoStopsItIsTheStraightLineAtHalfTheAccelerationLimit) {
  // Zero tangents at both ends (from a stop, to a 3 s hold): the Hermite curve is the chord. The
  // target speeds up at 0.5 x WPNAV_ACCEL = 1.25 m/s^2 to 10 m/s (8 s, 40 m), cruises 120 m (12 s)
  // and brakes on sqrt(2 x 1.25 x distance left) (8 s): 28 s for 200 m in continuous time. Stepped
  // at 0.01 s, the braking law is evaluated where the target was a step before and it arrives
  // earlier (27.54 s for this 1-D law by hand at 0.01 s).
  const Mission m = localMission({{200, 0, 10}}, 3.0, 0.0, true, 82);
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{}, onTarget());
  const double leg_s = f.events[1].reached_s - f.events[0].completed_s;
  EXPECT_GT(leg_s, 27.5);
  EXPECT_LT(leg_s, 28.0);
  EXPECT_NEAR(f.events[1].completed_s - f.events[1].reached_s, 3.0, 0.02);
  double off_line = 0.0, v_max = 0.0, a_max = 0.0;
  for (std::size_t i = 1; i < f.samples.size(); ++i) {
    const auto& s = f.samples[i];
    if (s.t < f.events[0].completed_s || s.t > f.events[1].reached_s) continue;
    off_line = std::max(off_line, std::abs(s.position.y()));
    v_max = std::max(v_max, s.velocity.norm());
    a_max = std::max(a_max, std::abs(s.velocity.norm() - f.samples[i - 1].velocity.norm()) / (s.t - f.samples[i - 1].t));
  }
  EXPECT_LT(off_line, 1e-6);
  EXPECT_NEAR(v_max, 10.0, 1e-6);
  EXPECT_LT(a_max, 1.25 + 1e-6);
  EXPECT_GT(a_max, 1.2);
}

TEST(ArduCopterSpline, ThroughSplineWaypointsTheCurveIsFlownAtSpeedAndTheLateralShareMatters) {
  // Tangent at each inner waypoint: next minus previous (AC_WPNav::set_spline_destination).
  const std::vector<Eigen::Vector3d> wps{{0, 100, 10}, {100, 100, 10}, {100, 0, 10}, {200, 0, 10}};
  const Mission m = localMission(wps, 0.0, 0.0, true, 82);
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{}, onTarget());
  for (const auto& w : wps) EXPECT_LT(closestTo(f, w), 0.6) << w.transpose();  // samples 0.1 s apart
  const double t0 = f.events[1].reached_s, t3 = f.events[4].reached_s;
  EXPECT_GT(minSpeedBetween(f, t0 + 0.5, t3 - 8.0), 3.0);  // flown through; the last one is a stop (RTL next)
  // The curvature caps the speed at 0.5 x WPNAV_ACCEL sideways, but the speed may fall only at
  // 0.5 x WPNAV_ACCEL along the curve and SplineCurve does not look ahead: where the curve
  // tightens the target runs above its cap for a moment (within the 2.5 m/s^2 limit here).
  const double lateral = largestLateralAcceleration(f, t0, t3);
  EXPECT_GT(lateral, 1.0);
  EXPECT_LT(lateral, 2.5);
  // Longer than the polyline (300 m): the curves swing out.
  double path = 0.0;
  for (std::size_t i = 1; i < f.samples.size(); ++i)
    if (f.samples[i].t > t0 && f.samples[i].t <= t3) path += (f.samples[i].position - f.samples[i - 1].position).norm();
  EXPECT_GT(path, 310.0);
  // Before ArduPilot 4.2 the curvature could use the whole acceleration limit: faster through and
  // harder sideways.
  AutopilotConfig old;
  old.version = "4.1.5";
  const FlownMission f41 = flyMission(sequenceMission(m), old, onTarget());
  const double t0_41 = f41.events[1].reached_s, t3_41 = f41.events[4].reached_s;
  EXPECT_LT(t3_41 - t0_41, t3 - t0 - 1.0);
  EXPECT_GT(largestLateralAcceleration(f41, t0_41, t3_41), lateral);
}

TEST(ArduCopterSpline, AStraightLegMeetsASplineOnItsWaypointAtSpeed) {
  // 100 m east (a waypoint), a spline to (200, 50), a waypoint at (300, 50): the straight leg ends
  // on its waypoint at the speed the spline can start at, without a stop and without the corner
  // blend two straight legs would get (which cuts it by about WPNAV_RADIUS).
  const std::vector<Eigen::Vector3d> wps{{100, 0, 10}, {200, 50, 10}, {300, 50, 10}};
  Mission m = localMission(wps);
  m.items[2].command = 82;  // take-off, waypoint, spline, waypoint, RTL
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{}, onTarget());
  EXPECT_LT(closestTo(f, wps[0]), 0.5);
  EXPECT_GT(minSpeedBetween(f, f.events[1].reached_s - 3.0, f.events[2].reached_s), 2.0);
  const FlownMission straight = flyMission(sequenceMission(localMission(wps)), AutopilotConfig{}, onTarget());
  EXPECT_GT(closestTo(straight, wps[0]), 1.0);
}

TEST(ArduCopterSpline, ASplineFliesThroughIntoALandingsApproachAtSpeed) {
  // Take-off to 10 m, a spline to (0, 100), NAV_LAND at (0, 200): ModeAuto::get_spline_from_cmd
  // takes the LAND's location as the spline's exit, set_next_wp plans no leg after it, and the
  // landing's approach (FlyToLocation, wp_start) starts at the spline's target speed. So the
  // vehicle passes the spline's waypoint at speed, leaving it towards the landing point, where a
  // NAV_WAYPOINT there would stop it (set_next_wp: always a stop before LAND). A hold on the spline
  // stops it too.
  const auto flight = [](int command, double hold) {
    Mission m = localMission({{0, 100, 10}}, hold, 0.0, false);
    m.items[1].command = command;  // take-off, the (spline) waypoint
    MissionItem land = m.items.back();
    land.seq += 1;
    land.command = 21;
    land.param[0] = 0.0;
    const wattswath::geometry::LocalFrame frame(m.home);
    const auto g = frame.toGeodetic({0.0, 200.0});
    land.lat_deg = g.lat_deg;
    land.lon_deg = g.lon_deg;
    land.alt_m = 0.0;
    m.items.push_back(land);
    return flyMission(sequenceMission(m), AutopilotConfig{}, onTarget());
  };
  const FlownMission spline = flight(82, 0.0), straight = flight(16, 0.0), held = flight(82, 1.0);
  const double t = spline.events[1].reached_s;
  EXPECT_GT(minSpeedBetween(spline, t - 1.0, t + 1.0), 5.0);
  EXPECT_LT(minSpeedBetween(straight, straight.events[1].reached_s - 1.0, straight.events[1].reached_s + 1.0), 0.5);
  EXPECT_LT(minSpeedBetween(held, held.events[1].reached_s - 1.0, held.events[1].reached_s + 1.0), 0.5);
  // Landing begins over (0, 200) in every case; through the spline it does so sooner.
  EXPECT_LT(spline.events[2].reached_s + 3.0, straight.events[2].reached_s);
  EXPECT_LT(closestTo(spline, {0.0, 200.0, 10.0}), 0.5);
}

TEST(ArduCopterSpline, TheFirstSplineOfAChainFromRestIsLimitedByTheNextLegObjectsStaleArrival) {
  // Splines to (0, 100), (0, 110) and (0, 300), in a line, from rest after the take-off. AC_WPNav
  // builds the second spline in its next-leg object, whose origin speed limit includes the stopping
  // clause sqrt(2 (0.5 WPNAV_ACCEL) chord + v^2) with v the arrival limit that object still holds:
  // 0 at boot, so sqrt(2 x 1.25 x 10) = 5.0 m/s, and the first spline arrives at 5.0 m/s, not the
  // 10 m/s its own unlimited arrival would allow (SplineCurve::set_origin_and_destination).
  Mission m = localMission({{0, 100, 10}, {0, 110, 10}, {0, 300, 10}});
  for (int i : {1, 2, 3}) m.items[static_cast<std::size_t>(i)].command = 82;  // take-off, 3 splines, RTL
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{}, onTarget());
  double at_wp1 = 0.0, before = 0.0;
  for (const auto& s : f.samples) {
    if (s.t <= f.events[1].reached_s) at_wp1 = s.velocity.norm();
    if (s.phase == FlightPhase::Mission && s.position.y() < 90.0) before = std::max(before, s.velocity.norm());
  }
  EXPECT_NEAR(at_wp1, 5.0, 0.15);
  EXPECT_GT(before, 6.0);  // it flew faster earlier on the first spline and slowed for the short one
}

namespace {

AutopilotConfig arduCopter33() {
  AutopilotConfig ap;
  ap.firmware = "ArduCopter";
  ap.version = "3.3";
  ap.family = familyOf(ap.firmware, ap.version);
  return ap;
}

}  // namespace

TEST(ArduCopterLeashSpline, BetweenTwoStopsTheTargetRampsAtWpnavAccelAndBrakesOnTheSquareRootLaw) {
  // 3.3 defaults: WPNAV_SPEED 5 m/s, WPNAV_ACCEL 1 m/s^2. The target speeds up at 1 m/s^2 (5 s,
  // 12.5 m), cruises, and within 5^2 / (4 x 1) = 6.25 m of the stop drops to sqrt(2 x 1 x d)
  // (3.54 m/s at once, then 3.54 s to the point): 5 + 181.25 / 5 + 3.54 = 44.8 s for 200 m on
  // the chord (both tangents the chord x 0.02), give or take the 0.1 s navigation clock.
  const Mission m = localMission({{200, 0, 10}}, 3.0, 0.0, true, 82);
  const FlownMission f = flyMission(sequenceMission(m), arduCopter33());
  EXPECT_NEAR(f.events[1].reached_s - f.events[0].completed_s, 44.8, 0.7);
  double off_line = 0.0, v_max = 0.0;
  for (const auto& s : f.samples) {
    if (s.t < f.events[0].completed_s || s.t > f.events[1].reached_s) continue;
    off_line = std::max(off_line, std::abs(s.position.y()));
    v_max = std::max(v_max, s.velocity.norm());
  }
  EXPECT_LT(off_line, 0.01);
  EXPECT_NEAR(v_max, 5.0, 0.2);
}

TEST(ArduCopterLeashSpline, ThroughSplineWaypointsItFollowsTheSameCurveAt3xSpeeds) {
  // The same Hermite path as 4.x (tangents next minus previous), flown by a 3.x target that speeds
  // up at WPNAV_ACCEL within its leash: it swings out past y = 100 like the curve and never stops.
  const std::vector<Eigen::Vector3d> wps{{0, 100, 10}, {100, 100, 10}, {100, 0, 10}, {200, 0, 10}};
  const Mission m = localMission(wps, 0.0, 0.0, true, 82);
  const FlownMission f = flyMission(sequenceMission(m), arduCopter33());
  const FlownMission target = flyMission(sequenceMission(m), AutopilotConfig{}, onTarget());
  double y_max = 0.0, y_max_target = 0.0;
  for (const auto& s : f.samples) y_max = std::max(y_max, s.position.y());
  for (const auto& s : target.samples) y_max_target = std::max(y_max_target, s.position.y());
  EXPECT_GT(y_max_target, 120.0);
  EXPECT_NEAR(y_max, y_max_target, 3.0);
  for (const auto& w : wps) EXPECT_LT(closestTo(f, w), 3.0) << w.transpose();
  EXPECT_GT(minSpeedBetween(f, f.events[1].reached_s, f.events[3].reached_s), 3.0);
}
