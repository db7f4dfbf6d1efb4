// NAV_LOITER_TURNS in the ArduCopter models against hand-worked cases: the time the circle's
// target takes (AC_Circle's ramp and rate), the vehicle's rotation, the move to the edge and the
// lag of the path inside the circle; PX4 refuses it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "flight_test_util.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/predict.hpp"

namespace {

using namespace wattswath::mission;
using wattswath::mission::testing::localMission;

constexpr double kPi = 3.14159265358979323846;

/// Take-off to 10 m, a waypoint at `wp`, a LOITER_TURNS round `center` (ENU [m]) of `turns` and
/// `radius` [m] (negative: counter-clockwise), a waypoint 60 m north-east of the centre, RTL.
Mission circleMission(const Eigen::Vector3d& wp, const Eigen::Vector3d& center, double turns, double radius) {
  Mission m = localMission({wp, center + Eigen::Vector3d(60, 60, 0)}, 0.0, 0.0, true);
  const wattswath::geometry::LocalFrame frame(m.home);
  MissionItem it;
  it.command = static_cast<int>(Command::NavLoiterTurns);
  it.frame = 3;
  it.param[0] = turns;
  it.param[2] = radius;
  const auto g = frame.toGeodetic({center.x(), center.y()});
  it.lat_deg = g.lat_deg;
  it.lon_deg = g.lon_deg;
  it.alt_m = center.z();
  it.where = "test loiter";
  m.items.insert(m.items.begin() + 2, it);  // after the take-off and the first waypoint
  for (std::size_t i = 0; i < m.items.size(); ++i) m.items[i].seq = static_cast<int>(i) + 1;
  return m;
}

AutopilotConfig arduCopter(const std::string& version) {
  AutopilotConfig ap;
  ap.firmware = "ArduCopter";
  ap.version = version;
  ap.family = familyOf(ap.firmware, ap.version);
  return ap;
}

/// [s] AC_Circle's time for `turns` at the limits: the target speeds up at
/// alpha = max(accel / r, 2 deg/s^2) to omega = min(rate, min(speed, sqrt(accel r / 2)) / r), or
/// turns them all while still speeding up.
double circleTime(double turns, double r, double rate_deg, double speed, double accel) {
  const double w = std::min(rate_deg * kPi / 180.0, std::min(speed, std::sqrt(0.5 * accel * r)) / r);
  const double alpha = std::max(accel / r, 2.0 * kPi / 180.0);
  const double angle = 2.0 * kPi * turns, ramp = w * w / (2.0 * alpha);
  return angle <= ramp ? std::sqrt(2.0 * angle / alpha) : w / alpha + (angle - ramp) / w;
}

int loiterStep(const FlownMission& f) {
  for (std::size_t k = 0; k < f.steps.size(); ++k)
    if (f.steps[k].kind == NavStep::Kind::LoiterTurns) return static_cast<int>(k);
  return -1;
}

/// The circling samples of `f` (from `skip` [s] after the circle starts to 1 s before it ends):
/// their median distance from `center`, median speed and the sign of their rotation (+1
/// counter-clockwise seen from above).
struct Circling {
  double radius = 0.0, speed = 0.0;
  int sense = 0;
};
Circling circling(const FlownMission& f, const Eigen::Vector3d& center, double skip) {
  const int k = loiterStep(f);
  const StepEvent& e = f.events[static_cast<std::size_t>(k)];
  std::vector<double> r, v;
  double turning = 0.0;
  for (const FlightSample& s : f.samples) {
    if (s.t < e.reached_s + skip || s.t > e.completed_s - 1.0) continue;
    const Eigen::Vector2d d = (s.position - center).head<2>();
    r.push_back(d.norm());
    v.push_back(s.velocity.head<2>().norm());
    turning += d.x() * s.velocity.y() - d.y() * s.velocity.x();
  }
  std::nth_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2), r.end());
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return {r[r.size() / 2], v[v.size() / 2], turning > 0.0 ? 1 : -1};
}

}  // namespace

// ArduCopter 4.5 defaults: WPNAV_SPEED 10 m/s, WPNAV_ACCEL 2.5 m/s^2, CIRCLE_RATE 20 deg/s. Radius
// 20 m: omega = min(0.349, min(10, sqrt(0.5 x 2.5 x 20) = 5) / 20) = 0.25 rad/s, alpha = 0.125
// rad/s^2; two turns: 2 s + (4 pi - 0.25) / 0.25 = 51.27 s.
TEST(LoiterTurns, ArduCopter4CirclesForTheTargetsRampAndRateAfterFlyingToTheEdge) {
  const Eigen::Vector3d center(0, 94, 10);
  const Mission m = circleMission({0, 50, 10}, center, 2, 20);
  const FlownMission f = flyMission(sequenceMission(m), arduCopter("4.5.7"));
  const int k = loiterStep(f);
  ASSERT_GE(k, 0);
  const StepEvent& e = f.events[static_cast<std::size_t>(k)];
  EXPECT_NEAR(e.completed_s - e.reached_s, circleTime(2, 20, 20, 10, 2.5), 0.05);
  EXPECT_NEAR(circleTime(2, 20, 20, 10, 2.5), 51.27, 0.01);
  // The prediction says how the circle is flown and what caps its rate.
  const bool noted = std::any_of(f.notes.begin(), f.notes.end(), [](const std::string& n) {
    return n.find("NAV_LOITER_TURNS: 2 turn(s) of 20 m clockwise") != std::string::npos &&
           n.find("capped by half the acceleration limit") != std::string::npos && n.find("51.27 s") != std::string::npos;
  });
  EXPECT_TRUE(noted);
  // It first flew to the closest point of the circle, (0, 74), and stopped there (WPNAV_RADIUS 2 m).
  for (const FlightSample& s : f.samples) {
    if (std::abs(s.t - e.reached_s) > 0.051) continue;
    EXPECT_LT((s.position - Eigen::Vector3d(0, 74, 10)).norm(), 2.0) << s.t;
  }
  // Clockwise seen from above (CIRCLE_RATE > 0), inside the circle (the input shaper lags its
  // target), at the target's angular rate.
  const Circling c = circling(f, center, 10.0);
  EXPECT_EQ(c.sense, -1);
  EXPECT_LT(c.radius, 20.0);
  EXPECT_GT(c.radius, 17.0);
  EXPECT_NEAR(c.speed, 0.25 * c.radius, 0.03 * 0.25 * c.radius);
}

TEST(LoiterTurns, NegativeRadiusCirclesCounterClockwiseAndNoLegWhenAlreadyOnTheEdge) {
  const Eigen::Vector3d center(0, 94, 10);
  // The waypoint before is on the circle: circle_movetoedge_start starts circling at once.
  const Mission m = circleMission({0, 74, 10}, center, 1, -20);
  const FlownMission f = flyMission(sequenceMission(m), arduCopter("4.5.7"));
  const int k = loiterStep(f);
  const StepEvent& before = f.events[static_cast<std::size_t>(k - 1)];
  const StepEvent& e = f.events[static_cast<std::size_t>(k)];
  EXPECT_NEAR(e.reached_s, before.completed_s, 0.011);
  EXPECT_NEAR(e.completed_s - e.reached_s, circleTime(1, 20, 20, 10, 2.5), 0.05);
  EXPECT_EQ(circling(f, center, 10.0).sense, 1);
}

// ArduCopter 3.x (leash model), its defaults: WPNAV_SPEED 5 m/s, WPNAV_ACCEL 1 m/s^2, POS_XY_P 1.
// Radius 20 m: omega = min(0.349, sqrt(0.5 x 1 x 20) / 20 = 0.158) rad/s, alpha = 0.05 rad/s^2. The
// vehicle chases the target point with the position controller alone (no feed-forward): at speed
// v it lags by e with v = sqrt(2 a (e - a / 2 p^2)) beyond a / p^2 = 1 m, on the circle of radius
// r' with r'^2 + e^2 = r^2 and v = omega r'. Solved: r' = 19.32 m.
TEST(LoiterTurns, ArduCopter3ChasesTheTargetOnTheCircleItsLagAllows) {
  const Eigen::Vector3d center(0, 94, 10);
  const Mission m = circleMission({0, 50, 10}, center, 2, 20);
  const FlownMission f = flyMission(sequenceMission(m), arduCopter("3.2.1"));
  const int k = loiterStep(f);
  const StepEvent& e = f.events[static_cast<std::size_t>(k)];
  EXPECT_NEAR(e.completed_s - e.reached_s, circleTime(2, 20, 20, 5, 1.0), 0.15);  // the target moves every 0.1 s
  const double w = std::sqrt(0.5 * 1.0 * 20) / 20;
  double lo = 10.0, hi = 20.0;  // bisect r' of the hand-worked balance
  for (int i = 0; i < 60; ++i) {
    const double rp = 0.5 * (lo + hi), lag = std::sqrt(400.0 - rp * rp), v = w * rp;
    (std::sqrt(2.0 * 1.0 * (lag - 0.5)) > v ? lo : hi) = rp;
  }
  EXPECT_NEAR(lo, 19.32, 0.01);
  const Circling c = circling(f, center, 15.0);
  EXPECT_NEAR(c.radius, lo, 0.1);
  EXPECT_NEAR(c.speed, w * c.radius, 0.03 * w * c.radius);
  EXPECT_EQ(c.sense, -1);
}

TEST(LoiterTurns, ACircleRateOfZeroIsAnErrorNotAFlightThatNeverEnds) {
  const Mission m = circleMission({0, 50, 10}, {0, 94, 10}, 2, 20);
  for (const char* version : {"4.5.7", "3.2.1"}) {
    AutopilotConfig ap = arduCopter(version);
    ap.parameters = {{"CIRCLE_RATE", 0.0}};
    try {
      flyMission(sequenceMission(m), ap);
      ADD_FAILURE() << version << ": no error";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("CIRCLE_RATE = 0"), std::string::npos) << e.what();
    }
  }
}

TEST(LoiterTurns, Px4RefusesItNamingTheItem) {
  const Mission m = circleMission({0, 50, 10}, {0, 94, 10}, 2, 20);
  AutopilotConfig px4;
  px4.firmware = "PX4";
  px4.version = "1.14.0";
  px4.family = familyOf(px4.firmware, px4.version);
  EXPECT_THROW(flyMission(sequenceMission(m), px4), std::invalid_argument);
}

TEST(LoiterTurns, TurnsAndRadiusAreKeptAsWholeNumbersAsArduPilotStoresThem) {
  const Mission m = circleMission({0, 50, 10}, {0, 94, 10}, 2.7, -20.9);
  const std::vector<NavStep> steps = sequenceMission(m);
  const auto it = std::find_if(steps.begin(), steps.end(), [](const NavStep& s) { return s.kind == NavStep::Kind::LoiterTurns; });
  ASSERT_NE(it, steps.end());
  EXPECT_DOUBLE_EQ(it->loiter_turns, 2.0);
  EXPECT_DOUBLE_EQ(it->loiter_radius_m, 20.0);
  EXPECT_TRUE(it->loiter_ccw);
  Mission bad = m;
  bad.items[2].param[2] = 0.5;  // below 1 m: ArduPilot keeps 0, a turn on the spot
  EXPECT_THROW(checkMission(bad), MissionError);
}

// Random circles (fixed seed): radius 1-120 m, 0-3 turns, either sense, speeds, accelerations and
// CIRCLE_RATE across their ranges, in both ArduCopter models. Each takes the closed-form time of its
// target (within a step; 3.x moves its target every 0.1 s); the vehicle starts within WPNAV_RADIUS
// of the edge and is within half a metre of the circle, or inside it, over the second half.
TEST(LoiterTurns, RandomCirclesTakeTheTargetsTimeAndStayInsideInBothModels) {
  std::mt19937 rng(20261127);
  std::uniform_real_distribution<double> radius(1.0, 120.0), speed(1.0, 15.0), accel(0.5, 5.0), rate(5.0, 90.0), turns(0.0, 3.0);
  for (int i = 0; i < 24; ++i) {
    const double r = std::floor(radius(rng)), n = std::floor(turns(rng)), v = speed(rng), a = accel(rng), w = rate(rng);
    const bool ccw = i % 2 == 1;
    for (const char* version : {"4.5.7", "3.2.1"}) {
      AutopilotConfig ap = arduCopter(version);
      ap.parameters = {{"WPNAV_SPEED", v * 100.0}, {"WPNAV_ACCEL", a * 100.0}, {"CIRCLE_RATE", w}};
      const Eigen::Vector3d center(0, 40.0 + r, 12);
      const FlownMission f = flyMission(sequenceMission(circleMission({0, 30, 12}, center, n, ccw ? -r : r)), ap);
      const int k = loiterStep(f);
      ASSERT_GE(k, 0);
      const StepEvent& e = f.events[static_cast<std::size_t>(k)];
      const bool three = version[0] == '3';
      EXPECT_NEAR(e.completed_s - e.reached_s, circleTime(n, r, w, v, a), three ? 0.15 : 0.03)
          << version << " r " << r << " turns " << n << " speed " << v << " accel " << a << " rate " << w;
      // Circling starts within WPNAV_RADIUS (2 m) of the edge and settles inside the circle.
      const double half = 0.5 * (e.reached_s + e.completed_s);
      for (const FlightSample& s : f.samples) {
        if (s.step != k || s.t < e.reached_s) continue;
        const double d = (s.position - center).head<2>().norm();
        EXPECT_LT(d, r + (s.t < half + 0.05 ? 2.5 : 0.5)) << version << " r " << r << " speed " << v << " accel " << a << " at " << s.t;
      }
    }
  }
}
