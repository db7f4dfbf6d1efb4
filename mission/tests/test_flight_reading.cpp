// How ArduPilot keeps and reads mission items before it flies them (AP_Mission's whole-second
// holds, ModeAuto::loc_from_cmd's latitude / longitude / altitude 0), in both ArduCopter models;
// PX4 reads them as written.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>

#include "flight_test_util.hpp"
#include "wattswath/mission/flight.hpp"

using namespace wattswath::mission;
using wattswath::mission::testing::localMission;
using wattswath::mission::testing::joined;
using wattswath::mission::testing::minSpeedBetween;

namespace {

AutopilotConfig arduCopter(const std::string& version) {
  return parseAutopilot(R"({"firmware":"ArduCopter","version":")" + version + R"("})", "test");
}

}  // namespace

TEST(ArduPilotReading, HoldsAreKeptInWholeSecondsSoHalfASecondIsFlownThrough) {
  // AP_Mission stores a waypoint's hold in a uint16 of seconds: 0.5 s is no hold (the waypoint is
  // flown through at speed), 2.7 s holds 2 s. PX4 holds the 0.5 s as written.
  for (const char* version : {"4.5", "3.3"}) {
    SCOPED_TRACE(version);
    Mission m = localMission({{100, 0, 10}, {200, 0, 10}, {300, 0, 10}});
    m.items[1].param[0] = 0.5;  // items: take-off, WP1, WP2, WP3, RTL
    m.items[2].param[0] = 2.7;
    const FlownMission f = flyMission(sequenceMission(m), arduCopter(version));
    EXPECT_GT(minSpeedBetween(f, f.events[1].reached_s - 1.0, f.events[1].reached_s + 1.0), 3.0);
    EXPECT_NEAR(f.events[2].completed_s - f.events[2].reached_s, 2.0, 0.05);
    const std::string notes = joined(f.notes);
    EXPECT_NE(notes.find("hold 0.5 s is kept by ArduPilot in whole seconds (0 s: no stop, flown through)"), std::string::npos) << notes;
    EXPECT_NE(notes.find("hold 2.7 s is kept by ArduPilot in whole seconds (2 s)"), std::string::npos);
  }
  Mission m = localMission({{100, 0, 10}, {200, 0, 10}});
  m.items[1].param[0] = 0.5;
  const FlownMission px4 = flyMission(sequenceMission(m), parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test"));
  EXPECT_NEAR(px4.events[1].completed_s - px4.events[1].reached_s, 0.5, 0.02);
}

TEST(ArduPilotReading, LatitudeLongitudeZeroClimbsOverThePreviousTargetAndAltitudeZeroKeepsIt) {
  // Take-off to 10 m, WP1 100 m east; WP2 with latitude and longitude 0 at 40 m: ArduPilot climbs
  // over WP1 to 40 m (ModeAuto::loc_from_cmd keeps the item's altitude); WP3 200 m east at
  // altitude 0: flown at the previous target's 40 m, not down to the ground.
  for (const char* version : {"4.5", "3.3"}) {
    SCOPED_TRACE(version);
    Mission m = localMission({{100, 0, 10}, {100, 0, 40}, {200, 0, 0}});
    m.items[2].lat_deg = m.items[2].lon_deg = 0.0;
    const FlownMission f = flyMission(sequenceMission(m), arduCopter(version));
    double top = 0.0, at_wp3 = 0.0;
    for (const auto& s : f.samples) {
      if (s.phase != FlightPhase::Mission) continue;
      top = std::max(top, s.position.z());
      if (s.t <= f.events[3].reached_s) at_wp3 = s.position.z();
    }
    EXPECT_NEAR(top, 40.0, 0.5);
    EXPECT_NEAR(at_wp3, 40.0, 0.5);  // 3.x flies through WP2 below it (the leash) and climbs on
    const std::string notes = joined(f.notes);
    EXPECT_NE(notes.find("latitude and longitude 0 are the previous target's for ArduPilot, flown to at the item's altitude 40 m"),
              std::string::npos)
        << notes;
    EXPECT_NE(notes.find("altitude 0 is the previous target's for ArduPilot (40 m)"), std::string::npos);
  }
}

TEST(ArduPilotReading, LandingDescendsAtWpnavSpeedDnWhateverDescentSpeedTheMissionSet) {
  // ModeAuto::land_start puts the descent limit back to WPNAV_SPEED_DN (the parameter), so a
  // DO_CHANGE_SPEED of type 3 (descent) to 3 m/s earlier in the mission does not speed the landing.
  const auto landingTime = [](bool changed) {
    Mission m = localMission({{100, 0, 50}}, 0.0, 0.0, false);
    MissionItem last = m.items.back();
    if (changed) {
      MissionItem speed = last;
      speed.seq += 1;
      speed.command = 178;
      speed.frame = 2;
      speed.param[0] = 3.0;  // descent speed
      speed.param[1] = 3.0;
      speed.lat_deg = speed.lon_deg = speed.alt_m = 0.0;
      m.items.push_back(speed);
    }
    MissionItem land = m.items.back();
    land.seq += 1;
    land.command = 21;
    land.lat_deg = land.lon_deg = land.alt_m = 0.0;
    m.items.push_back(land);
    const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{});
    double first = -1.0, last_t = 0.0;
    for (const auto& s : f.samples) {
      if (s.phase != FlightPhase::Landing) continue;
      if (first < 0.0) first = s.t;
      last_t = s.t;
    }
    return last_t - first;
  };
  const double plain = landingTime(false), changed = landingTime(true);
  EXPECT_GT(plain, 30.0);  // 50 m at WPNAV_SPEED_DN 1.5 m/s, then LAND_SPEED 0.5 m/s below LAND_ALT_LOW
  EXPECT_NEAR(changed, plain, 0.05);
}

TEST(ArduPilotReading, RtlNearHomeClimbsTwoAndAHalfMetresBefore45AndNotFrom45) {
  // Last waypoint 1 m from home at 10 m, then RTL (RTL_ALT 15 m, RTL_CONE_SLOPE 3): the cone's
  // 3 m is below the floor. Before 4.5 the floor is 2.5 m above the vehicle (RTL_ABS_MIN_CLIMB):
  // it returns at 12.5 m; from 4.5 the floor is the vehicle's altitude plus RTL_CLIMB_MIN (0): it
  // stays at 10 m (plus the hover offset of the climb leg); with RTL_CLIMB_MIN 3 m, at 13 m.
  const auto top = [](const std::string& version, const std::string& params) {
    const AutopilotConfig ap =
        parseAutopilot(R"({"firmware":"ArduCopter","version":")" + version + R"(","parameters":)" + params + "}", "test");
    const FlownMission f = flyMission(sequenceMission(localMission({{1, 0, 10}})), ap);
    double z = 0.0;
    for (const auto& s : f.samples)
      if (s.phase == FlightPhase::Return) z = std::max(z, s.position.z());
    return z;
  };
  EXPECT_NEAR(top("4.3", "{}"), 12.5, 0.05);
  EXPECT_NEAR(top("4.5", "{}"), 10.0, 0.05);
  EXPECT_NEAR(top("4.5", R"({"RTL_CLIMB_MIN":300})"), 13.0, 0.05);
}

TEST(ArduPilotReading, Before45ASpeedChangeRightAfterTheTakeoffIsLostUnlessItIsNotTheFirstDoItem) {
  // ArduPilot issue 21080: in 4.1-4.4 the first waypoint after the take-off restarts the waypoint
  // controller at WPNAV_SPEED (10 m/s by default), dropping the DO_CHANGE_SPEED that AP_Mission ran
  // as the take-off completed; a DO item placed before it runs first, so the speed change runs
  // after the waypoint started and is kept. 4.5 keeps it either way. A later change (before WP2)
  // works in every version.
  const auto topSpeeds = [](const std::string& version, bool camera_first) {
    Mission m = localMission({{600, 0, 10}, {600, 600, 10}}, 0.0, 5.0);  // take-off, speed 5, WP1, WP2, RTL
    if (camera_first) {
      MissionItem cam = m.items[1];
      cam.command = 206;  // DO_SET_CAM_TRIGG_DIST
      cam.param[0] = 20.0;
      cam.param[1] = 0.0;
      m.items.insert(m.items.begin() + 1, cam);
    }
    MissionItem later = m.items[camera_first ? 2 : 1];  // a copy of the speed change, at 7 m/s before WP2
    later.param[1] = 7.0;
    m.items.insert(m.items.end() - 2, later);  // before WP2
    for (std::size_t i = 0; i < m.items.size(); ++i) m.items[i].seq = static_cast<int>(i) + 1;
    const AutopilotConfig ap = parseAutopilot(R"({"firmware":"ArduCopter","version":")" + version + R"("})", "test");
    const FlownMission f = flyMission(sequenceMission(m), ap);
    double leg1 = 0.0, leg2 = 0.0;
    for (const auto& s : f.samples) {
      if (s.phase != FlightPhase::Mission) continue;
      const double v = s.velocity.head<2>().norm();
      if (s.position.x() < 500.0) leg1 = std::max(leg1, v);
      if (s.position.y() > 100.0 && s.position.y() < 500.0) leg2 = std::max(leg2, v);
    }
    return std::make_tuple(leg1, leg2, joined(f.notes));
  };
  const auto [lost, lost2, lost_notes] = topSpeeds("4.3", false);
  EXPECT_NEAR(lost, 10.0, 0.05);
  EXPECT_NEAR(lost2, 7.0, 0.05);
  EXPECT_NE(lost_notes.find("ArduCopter 4.3 drops a DO_CHANGE_SPEED run just before the first waypoint after a take-off"),
            std::string::npos)
      << lost_notes;
  const auto [kept, kept2, kept_notes] = topSpeeds("4.3", true);
  EXPECT_NEAR(kept, 5.0, 0.05);
  EXPECT_NEAR(kept2, 7.0, 0.05);
  EXPECT_EQ(kept_notes.find("drops a DO_CHANGE_SPEED"), std::string::npos);
  const auto [fixed, fixed2, fixed_notes] = topSpeeds("4.5", false);
  EXPECT_NEAR(fixed, 5.0, 0.05);
  EXPECT_NEAR(fixed2, 7.0, 0.05);
}

TEST(ArduPilotReading, ASpeedChangeAfterAConditionSaysItWaitsForIt) {
  // AP_Mission runs the DO items after a CONDITION_DELAY only once its time is up (and drops them
  // if the next waypoint comes first): the speed change after it gets a warning naming the item.
  Mission m = localMission({{200, 0, 10}, {400, 0, 10}}, 0.0, 5.0);  // take-off, speed, WP1, WP2, RTL
  MissionItem wait = m.items[1];
  wait.command = 112;  // CONDITION_DELAY
  wait.param[0] = 30.0;
  wait.where = "test item wait";
  MissionItem speed = m.items[1];
  speed.param[1] = 3.0;
  speed.where = "test item late speed";
  m.items.insert(m.items.begin() + 3, {wait, speed});  // between WP1 and WP2
  for (std::size_t i = 0; i < m.items.size(); ++i) m.items[i].seq = static_cast<int>(i) + 1;
  std::vector<std::string> warnings;
  (void)sequenceMission(m, &warnings);
  const std::string all = joined(warnings);
  EXPECT_NE(all.find("test item late speed: DO_CHANGE_SPEED after a CONDITION_DELAY or CONDITION_DISTANCE: ArduPilot runs it "
                     "only once that condition is met"),
            std::string::npos)
      << all;
  // The first speed change, with no condition before it, gets none.
  EXPECT_EQ(all.find("test item 2:"), std::string::npos);
}

TEST(ArduPilotReading, ANavDelayOfZeroSecondsSaysArduPilotWaitsForATimeOfDay) {
  // ModeAuto::do_nav_delay: param1 <= 0 waits until the UTC time of day in param2-4.
  Mission m = localMission({{100, 0, 10}});
  MissionItem delay = m.items[1];
  delay.command = 93;
  delay.param[0] = 0.0;
  delay.param[1] = 14.0;
  delay.param[2] = 30.0;
  delay.param[3] = 0.0;
  delay.lat_deg = delay.lon_deg = delay.alt_m = 0.0;
  delay.where = "test item delay";
  m.items.insert(m.items.begin() + 2, delay);
  for (std::size_t i = 0; i < m.items.size(); ++i) m.items[i].seq = static_cast<int>(i) + 1;
  std::vector<std::string> warnings;
  (void)sequenceMission(m, &warnings);
  EXPECT_NE(joined(warnings).find("test item delay: NAV_DELAY of 0 s: ArduPilot takes a delay that is not positive as a "
                                  "wait until the time of day in param2-4 (14:30:00 UTC)"),
            std::string::npos)
      << joined(warnings);
  m.items[2].param[0] = 5.0;
  warnings.clear();
  (void)sequenceMission(m, &warnings);
  EXPECT_EQ(joined(warnings).find("NAV_DELAY"), std::string::npos);
}

TEST(ArduPilotReading, ALandingOverTheWaypointJustReachedStillFliesItsShortApproachLeg) {
  // ModeAuto::do_land flies to the LAND's point at the measured altitude (shift_alt_to_current_alt):
  // over the waypoint the vehicle stopped at, a leg of about a centimetre, which AC_WPNav flies as
  // a whole S-curve (0.6-1.1 s at the defaults), as the 4.7 SITL logs show before an RTL's return.
  Mission m = localMission({{100, 0, 10}}, 1.0, 0.0, false);
  MissionItem land = m.items.back();
  land.seq += 1;
  land.command = 21;
  land.param[0] = 0.0;
  land.alt_m = 0.0;
  m.items.push_back(land);  // at the waypoint's latitude and longitude
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{});
  double descent = -1.0;
  for (const auto& s : f.samples)
    if (s.t > f.events[1].completed_s && s.velocity.z() < -0.05) {
      descent = s.t;
      break;
    }
  ASSERT_GT(descent, 0.0);
  EXPECT_GT(descent - f.events[1].completed_s, 0.6);
  EXPECT_LT(descent - f.events[1].completed_s, 1.6);
}

TEST(ArduPilotReading, AHereItemThatDoesNotMoveTheVehicleAndAHereCircleAreSaid) {
  // An item with latitude, longitude and altitude 0 flies to the previous target, where the
  // vehicle already is (ArduPilot's PAUSE_CONTINUE test mission ends so); a LOITER_TURNS with
  // latitude and longitude 0 circles round where the vehicle is. Both were flown without a word.
  Mission m = localMission({{100, 0, 10}, {0, 0, 0}});
  m.items[2].lat_deg = m.items[2].lon_deg = 0.0;  // items: take-off, WP1, WP2 "here", RTL
  std::string notes = joined(flyMission(sequenceMission(m), arduCopter("4.5")).notes);
  EXPECT_NE(notes.find("test item 3: latitude, longitude and altitude 0 are the previous target's for ArduPilot, where the "
                       "vehicle already is: a leg of no length"),
            std::string::npos) << notes;
  // With its altitude given, and the vehicle's (ArduPilot's inf_loop: a LOITER_TIME here at 100 m
  // after the climb to 100 m), the note does not call that altitude 0.
  Mission a = localMission({{100, 0, 10}, {0, 0, 10}});
  a.items[2].lat_deg = a.items[2].lon_deg = 0.0;
  notes = joined(flyMission(sequenceMission(a), arduCopter("4.5")).notes);
  EXPECT_NE(notes.find("test item 3: latitude and longitude 0 are the previous target's for ArduPilot, and its altitude, 10 m, "
                       "is the vehicle's: a leg of no length"),
            std::string::npos) << notes;
  Mission c = localMission({{100, 0, 10}, {0, 0, 0}});
  c.items[2].command = 18;  // NAV_LOITER_TURNS here, 1 turn of 5 m
  c.items[2].lat_deg = c.items[2].lon_deg = 0.0;
  c.items[2].param[0] = 1.0;
  c.items[2].param[2] = 5.0;
  notes = joined(flyMission(sequenceMission(c), arduCopter("4.5")).notes);
  EXPECT_NE(notes.find("test item 3: latitude and longitude 0: ArduPilot circles round where the vehicle is, at the previous "
                       "target's altitude"),
            std::string::npos) << notes;
}

TEST(ArduPilotReading, ATakeOffInTheAirBelowTheVehicleIsCompleteAtOnceAndRtlAltZeroReturnsAtTheCurrentAltitude) {
  // ModeAuto::takeoff_start floors the target 1 m above the vehicle only when it is landed: a
  // second NAV_TAKEOFF to 10 m flown at 20 m is complete at once (the model climbed 1 m there).
  Mission m = localMission({{100, 0, 20}, {200, 0, 20}});
  MissionItem again = m.items[0];  // items: take-off 20 m, WP1, WP2, RTL
  again.alt_m = 10.0;
  again.where = "test take-off in the air";
  m.items.insert(m.items.begin() + 2, again);
  for (std::size_t k = 0; k < m.items.size(); ++k) m.items[k].seq = static_cast<int>(k) + 1;
  const FlownMission f = flyMission(sequenceMission(m), arduCopter("4.5"));
  ASSERT_EQ(f.steps[2].kind, NavStep::Kind::Takeoff);
  EXPECT_NEAR(f.events[2].completed_s, f.events[2].reached_s, 1e-9);
  double top = 0.0;
  for (const FlightSample& s : f.samples) top = std::max(top, s.position.z());
  EXPECT_LT(top, 20.2);
  // RTL_ALT 0: ModeRTL::compute_return_target takes max(RTL_ALT, RTL_ALT_MIN 0.3 m, ...), so the
  // return flies at the current 20 m (the model refused RTL_ALT below 30 cm).
  const AutopilotConfig zero =
      parseAutopilot(R"({"firmware":"ArduCopter","version":"4.5","parameters":{"RTL_ALT":0}})", "test");
  const FlownMission r = flyMission(sequenceMission(localMission({{100, 0, 20}})), zero);
  double highest = 0.0;
  for (const FlightSample& s : r.samples) highest = std::max(highest, s.position.z());
  EXPECT_NEAR(highest, 20.0, 0.3);
}

TEST(ArduPilotReading, From33ThePositionControllerJerkLimitsAndFiltersItsAccelerationTarget) {
  // AC_PosControl::accel_to_lean_angles from 3.3 limits the change of the acceleration target to
  // 17 m/s^3 and low-pass filters it at PSC_ACC_XY_FILT (2 Hz); 3.2 converts it as it is. On a
  // mission of sharp turns at 10 m/s with WPNAV_ACCEL 5 m/s/s the horizontal jerk of the simulated
  // vehicle (every 0.01 s) stays within 17 m/s^3 on 3.3, and exceeds it on 3.2, whose lean target
  // jumps ten times a second (accelerations averaged over 0.1 s, the controller's period).
  Mission m = localMission({{60, 0, 10}, {10, 20, 10}, {70, 40, 10}, {0, 60, 10}}, 0.0, 10.0);
  FlightSettings s;
  s.sample_dt = s.dt;
  auto jerk = [&](const char* version) {
    const AutopilotConfig ap = parseAutopilot(R"({"firmware":"ArduCopter","version":")" + std::string(version) +
                                              R"(","parameters":{"WPNAV_ACCEL":500}})", "test");
    const FlownMission f = flyMission(sequenceMission(m), ap, s);
    double most = 0.0;
    const std::size_t w = 10;  // 0.1 s: the controller's period before 3.4
    for (std::size_t i = 2 * w; i < f.samples.size(); ++i) {
      const auto& a = f.samples[i - 2 * w];
      const auto& b = f.samples[i - w];
      const auto& c = f.samples[i];
      if (!a.airborne || a.phase != FlightPhase::Mission || c.phase != FlightPhase::Mission) continue;
      const Eigen::Vector2d acc1 = (b.velocity - a.velocity).head<2>() / (b.t - a.t);
      const Eigen::Vector2d acc2 = (c.velocity - b.velocity).head<2>() / (c.t - b.t);
      most = std::max(most, (acc2 - acc1).norm() / (c.t - b.t));
    }
    return most;
  };
  const double j33 = jerk("3.3"), j32 = jerk("3.2");
  EXPECT_LT(j33, 17.5) << j33;
  EXPECT_GT(j32, 25.0) << j32;  // 15.5 and 28 m/s^3 when written
}
