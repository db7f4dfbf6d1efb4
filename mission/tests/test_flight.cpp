// Flight-behaviour models against hand-worked cases: an S-curve leg reaches its speed with the
// jerk and acceleration ramps ArduCopter derives; a 90 degree corner is blended at the speed the
// overlap allows; a hold stops the vehicle; PX4's corner speed and straight-leg timing; the
// leash model's stop; bad inputs give clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "flight_test_util.hpp"
#include "wattswath/mission/flight.hpp"
#include "wattswath/mission/scurve.hpp"

using namespace wattswath::mission;
using wattswath::mission::testing::liftoffTime;
using wattswath::mission::testing::localMission;
using wattswath::mission::testing::maxSpeedBetween;
using wattswath::mission::testing::minSpeedBetween;


TEST(SCurve, LongLegReachesSpeedWithTheDerivedRamps) {
  // ArduCopter 4.x defaults: V 10 m/s, A 2.5 m/s^2, J 1 m/s^3, snap 5.236 m/s^4 -> tj = 0.3 s;
  // T_acc = V/A + tj + A/J = 6.8 s, D_acc = V T_acc / 2 = 34 m; a 200 m leg takes 2 T_acc + (200 - 68)/10.
  const SCurveLimits lim{10.0, 2.5, 1.0, 1.0 * M_PI / 0.3 * 0.5};
  const SCurveProfile p = SCurveProfile::restToRest(200.0, lim);
  EXPECT_NEAR(p.accelEndTime(), 6.8, 1e-6);
  EXPECT_NEAR(p.at(p.accelEndTime()).pos, 34.0, 1e-6);
  EXPECT_NEAR(p.peakSpeed(), 10.0, 1e-9);
  EXPECT_NEAR(p.duration(), 2 * 6.8 + 13.2, 1e-6);
  double a_max = 0.0, j_max = 0.0, prev_a = 0.0;
  for (double t = 0.0; t <= p.duration(); t += 0.001) {
    const TrackState s = p.at(t);
    a_max = std::max(a_max, std::abs(s.acc));
    if (t > 0.0) j_max = std::max(j_max, std::abs(s.acc - prev_a) / 0.001);
    prev_a = s.acc;
  }
  EXPECT_NEAR(a_max, 2.5, 1e-3);
  EXPECT_NEAR(j_max, 1.0, 5e-3);
  EXPECT_NEAR(p.at(p.duration()).pos, 200.0, 1e-9);
}

TEST(SCurve, ShortLegNeverReachesItsSpeedAndStillEndsAtRestOnTheTarget) {
  const SCurveLimits lim{10.0, 2.5, 1.0, 5.236};
  for (double L : {0.05, 1.0, 10.0, 60.0}) {
    const SCurveProfile p = SCurveProfile::restToRest(L, lim);
    EXPECT_LT(p.peakSpeed(), 10.0) << L;
    EXPECT_NEAR(p.at(p.duration()).pos, L, 1e-9) << L;
    EXPECT_NEAR(p.at(0.5 * p.duration()).pos, 0.5 * L, 1e-6 * L + 1e-9) << L;  // symmetric
    double prev = 0.0;
    for (double t = 0.0; t <= p.duration(); t += p.duration() / 500) {
      EXPECT_GE(p.at(t).pos + 1e-9, prev) << L;  // never backwards
      prev = p.at(t).pos;
    }
  }
}

TEST(SCurve, ALegJoinedAtSpeedKeepsTheRestToRestPeakAndEndsAtItsSpeeds) {
  // ArduCopter's SCurve::set_origin_speed_max / set_destination_speed_max: the peak stays the
  // rest-to-rest one; each end's speed change starts (or ends) at its own speed, so it is shorter.
  const SCurveLimits lim{10.0, 2.5, 1.0, 1.0 * M_PI / 0.3 * 0.5};
  const SCurveProfile rest = SCurveProfile::restToRest(200.0, lim);
  const SCurveProfile joined = SCurveProfile::between(200.0, 4.0, 6.0, lim);
  EXPECT_NEAR(joined.at(0.0).vel, 4.0, 1e-12);
  EXPECT_NEAR(joined.at(joined.duration()).vel, 6.0, 1e-12);
  EXPECT_NEAR(joined.at(joined.duration() - 1e-6).vel, 6.0, 1e-4);  // continuous at the end
  EXPECT_NEAR(joined.at(joined.duration()).pos, 200.0, 1e-9);
  EXPECT_NEAR(joined.peakSpeed(), rest.peakSpeed(), 1e-6);
  EXPECT_LT(joined.duration(), rest.duration());
  // End speeds above the peak are cut to it; negative ones are an error.
  const SCurveProfile short_leg = SCurveProfile::between(10.0, 20.0, 20.0, lim);
  EXPECT_NEAR(short_leg.at(0.0).vel, SCurveProfile::restToRest(10.0, lim).peakSpeed(), 1e-9);
  EXPECT_THROW(SCurveProfile::between(10.0, -1.0, 0.0, lim), std::invalid_argument);
}

// Largest |acceleration| and |jerk| of `p`, sampled every 1 ms.
std::pair<double, double> accelAndJerkMax(const SCurveProfile& p) {
  double a_max = 0.0, j_max = 0.0, prev_a = 0.0;
  for (double t = 0.0; t <= p.duration(); t += 0.001) {
    const double a = p.at(t).acc;
    a_max = std::max(a_max, std::abs(a));
    if (t > 0.0) j_max = std::max(j_max, std::abs(a - prev_a) / 0.001);
    prev_a = a;
  }
  return {a_max, j_max};
}

TEST(SCurve, ASpeedRaisedDuringTheAccelerationIsReachedByASecondSpeedChange) {
  // SCurve::set_speed_max during the acceleration: the first speed change is kept and a second one
  // follows it. Hand-worked with A 2.5 m/s^2, J 1 m/s^3, tj 0.3 s: a change of 5 m/s peaks at the
  // root of a^2 + tj a = 5 (2.091 m/s^2) and lasts 2 (a / J + tj) = 4.782 s; 0 -> 10 m/s lasts
  // 6.8 s over 34 m. So 0 -> 5 -> 10 m/s takes 9.564 s over 11.955 + 35.866 m, and the 200 m leg
  // 4.782 + 4.782 + (200 - 47.82 - 34) / 10 + 6.8 = 28.18 s, 1.38 s more than planned at 10 m/s.
  const SCurveLimits lim{5.0, 2.5, 1.0, 1.0 * M_PI / 0.3 * 0.5};
  SCurveProfile p = SCurveProfile::restToRest(200.0, lim);
  const TrackState before = p.at(1.0);
  p.setSpeedMax(1.0, 10.0);
  const TrackState after = p.at(1.0);
  EXPECT_NEAR(after.pos, before.pos, 1e-12);  // the flown part is not changed
  EXPECT_NEAR(after.vel, before.vel, 1e-12);
  EXPECT_NEAR(after.acc, before.acc, 1e-12);
  EXPECT_NEAR(p.at(4.782).vel, 5.0, 2e-3);  // the first change ends at the old speed
  EXPECT_NEAR(std::abs(p.at(4.782).acc), 0.0, 2e-3);
  EXPECT_NEAR(p.peakSpeed(), 10.0, 1e-6);
  EXPECT_NEAR(p.speedMax(), 10.0, 0.0);
  EXPECT_NEAR(p.at(9.564).vel, 10.0, 2e-3);
  EXPECT_NEAR(p.duration(), 28.18, 5e-3);
  EXPECT_NEAR(p.duration() - SCurveProfile::restToRest(200.0, {10.0, 2.5, 1.0, lim.snap}).duration(), 1.38, 5e-3);
  EXPECT_NEAR(p.at(p.duration()).pos, 200.0, 1e-9);
  EXPECT_NEAR(p.at(p.duration()).vel, 0.0, 1e-9);
  const auto [a_max, j_max] = accelAndJerkMax(p);
  EXPECT_LE(a_max, 2.5 + 1e-6);
  EXPECT_LE(j_max, 1.0 + 5e-3);
}

TEST(SCurve, ASpeedLoweredInTheCruiseOrTheAccelerationAndNothingOnceBraking) {
  const double snap = 1.0 * M_PI / 0.3 * 0.5;
  // In the cruise (200 m at 10 m/s, t = 10 s, 66 m flown): 10 -> 5 m/s within half the 100 m
  // of cruise left (4.782 s, 35.87 m), then 5 m/s, then 5 -> 0 (4.782 s, 11.955 m):
  // 10 + 4.782 + (200 - 66 - 35.87 - 11.955) / 5 + 4.782 = 36.80 s.
  SCurveProfile cruise = SCurveProfile::restToRest(200.0, {10.0, 2.5, 1.0, snap});
  cruise.setSpeedMax(10.0, 5.0);
  EXPECT_NEAR(cruise.at(10.0).pos, 66.0, 1e-9);
  EXPECT_NEAR(cruise.at(14.782).vel, 5.0, 2e-3);
  EXPECT_NEAR(cruise.duration(), 36.80, 5e-3);
  EXPECT_NEAR(cruise.at(cruise.duration()).pos, 200.0, 1e-9);
  // In the constant acceleration (t = 3 s of 2.8-4.0 s): the acceleration is cut short. The
  // slowest it can still end at is 10 - 2.5 (4 - 3) = 7.5 m/s (0.2 s of constant acceleration, at
  // 5.8 s over 21.75 m); then 7.5 -> 6 m/s (peak root of a^2 + 0.3 a = 1.5: 2.768 s, 18.68 m),
  // 6 m/s, and 6 -> 0 (5.208 s, 15.62 m): 5.8 + 2.768 + 143.95 / 6 + 5.208 = 37.77 s.
  SCurveProfile accel = SCurveProfile::restToRest(200.0, {10.0, 2.5, 1.0, snap});
  const TrackState at3 = accel.at(3.0);
  accel.setSpeedMax(3.0, 6.0);
  EXPECT_NEAR(accel.at(3.0).vel, at3.vel, 1e-9);
  EXPECT_NEAR(accel.at(5.8).vel, 7.5, 2e-3);
  EXPECT_NEAR(accel.peakSpeed(), 6.0, 1e-6);
  EXPECT_NEAR(accel.duration(), 37.77, 1e-2);
  const auto [a_max, j_max] = accelAndJerkMax(accel);
  EXPECT_LE(a_max, 2.5 + 1e-6);
  EXPECT_LE(j_max, 1.0 + 5e-3);
  // Braking has begun (t = 21 s of the 26.8 s leg): nothing changes but the stored limit.
  SCurveProfile braking = SCurveProfile::restToRest(200.0, {10.0, 2.5, 1.0, snap});
  braking.setSpeedMax(21.0, 3.0);
  EXPECT_NEAR(braking.duration(), 26.8, 1e-6);
  EXPECT_EQ(braking.speedMax(), 3.0);
  // Before the start: planned anew; a cruise of under 12 jerk times per m/s: no speed change
  // (30 m at 5 m/s cruises 6.09 m, 6.09 / 3.6 s < 5 m/s); a speed of 0 is ignored.
  SCurveProfile fresh = SCurveProfile::restToRest(200.0, {5.0, 2.5, 1.0, snap});
  fresh.setSpeedMax(0.0, 10.0);
  EXPECT_NEAR(fresh.duration(), 26.8, 1e-6);
  SCurveProfile short_leg = SCurveProfile::restToRest(30.0, {5.0, 2.5, 1.0, snap});
  const double short_duration = short_leg.duration();
  short_leg.setSpeedMax(1.0, 10.0);
  EXPECT_NEAR(short_leg.duration(), short_duration, 1e-9);
  EXPECT_NEAR(short_leg.peakSpeed(), 5.0, 1e-6);
  short_leg.setSpeedMax(1.0, 0.0);
  EXPECT_EQ(short_leg.speedMax(), 10.0);
}

TEST(SCurve, InFlightSpeedChangesKeepTheProfileContinuousWithinItsLimitsAndEndOnTheTarget) {
  // Random legs (0.1-500 m, 0.5-15.5 m/s, A 0.5-4.5 m/s^2, J 0.5-4.5 m/s^3) re-planned once or
  // twice at random times to random speeds (fixed seed): the flown part never changes, the target
  // never goes back, never jumps, never exceeds the acceleration limit and ends on the leg's end.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 2000; ++n) {
    SCOPED_TRACE(n);
    const double accel = 0.5 + 4.0 * u(rng), jerk = 0.5 + 4.0 * u(rng), tc = 0.1 + 0.4 * u(rng);
    const double length = std::pow(10.0, -1.0 + 3.7 * u(rng));
    SCurveProfile p = SCurveProfile::restToRest(length, {0.5 + 15.0 * u(rng), accel, jerk, 0.25 * jerk * M_PI / tc});
    double t = u(rng) < 0.1 ? 0.0 : u(rng) * p.duration();
    for (int k = 0; k < 1 + (u(rng) < 0.5); ++k) {
      if (k > 0) t += u(rng) * (p.duration() - t);
      const TrackState before = p.at(t);
      p.setSpeedMax(t, 0.3 + 20.0 * u(rng));
      if (t > 0.0) {
        ASSERT_NEAR(p.at(t).pos, before.pos, 1e-6);
        ASSERT_NEAR(p.at(t).vel, before.vel, 1e-6);
      }
    }
    ASSERT_TRUE(std::isfinite(p.duration()));
    const double dt = std::max(1e-4, (p.duration() - t) / 5000.0);
    TrackState prev = p.at(t);
    for (double s = t + dt; s <= p.duration() + dt; s += dt) {
      const TrackState x = p.at(s);
      ASSERT_GE(x.pos + 1e-9, prev.pos) << s;
      ASSERT_LE(x.pos - prev.pos, (std::max(prev.vel, x.vel) + 1e-3) * dt * 1.01 + 1e-6) << s;
      ASSERT_LE(std::abs(x.acc), accel * 1.0001 + 1e-9) << s;
      prev = x;
    }
    ASSERT_NEAR(p.at(p.duration()).pos, length, 1e-9);
  }
}

TEST(SCurve, RejectsLimitsThatAreNotPositive) {
  EXPECT_THROW(SCurveProfile::restToRest(10.0, {0.0, 2.5, 1.0, 5.0}), std::invalid_argument);
  EXPECT_THROW(SCurveProfile::restToRest(-1.0, {10.0, 2.5, 1.0, 5.0}), std::invalid_argument);
}

TEST(ArduCopterSCurve, NinetyDegreeCornerIsBlendedNotStopped) {
  // 200 m east, then 200 m north at 10 m/s (WPNAV_SPEED default): the corner is flown through at
  // about 2.9 m/s (docs/autopilots.md: WPNAV_RADIUS 2 m binds; overlap mid-point speed V cos 45 of
  // the accelerating/decelerating S-curves), never at rest.
  const Mission m = localMission({{200, 0, 10}, {200, 200, 10}});
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{});
  const double t_corner = f.events[1].reached_s;
  ASSERT_TRUE(std::isfinite(t_corner));
  const double v_min = minSpeedBetween(f, t_corner - 3.0, t_corner + 3.0);
  EXPECT_GT(v_min, 2.0);
  EXPECT_LT(v_min, 4.0);
  // The corner is cut by about WPNAV_RADIUS (2 m; the check is on the predicted mid-point, samples are 0.1 s apart).
  double closest = 1e9;
  for (const auto& s : f.samples) closest = std::min(closest, (s.position - Eigen::Vector3d(200, 0, 10)).norm());
  EXPECT_LT(closest, 2.1);
  EXPECT_GT(closest, 0.5);
}

TEST(ArduCopterSCurve, HoldTimeStopsTheVehicle) {
  const Mission m = localMission({{100, 0, 10}, {100, 100, 10}}, 3.0);
  FlightSettings exact;
  exact.airframe.track = false;  // the autopilot's target alone: the hand-worked S-curve
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{}, exact);
  const StepEvent& e = f.events[1];
  ASSERT_NEAR(e.completed_s - e.reached_s, 3.0, 0.02);
  EXPECT_LT(minSpeedBetween(f, e.reached_s, e.completed_s), 1e-6);
  // A stop-to-stop 100 m leg at 10 m/s: 2 x 6.8 s + (100 - 68) / 10 = 16.8 s after the take-off.
  EXPECT_NEAR(e.reached_s - f.events[0].reached_s, 16.8, 0.05);
}

// The vehicle chasing the target: it lags, the autopilot slows its S-curve clock, the leg takes
// longer than the target's 16.8 s, and during the hold the vehicle settles on the waypoint.
TEST(ArduCopterSCurve, TrackingVehicleLagsThenSettlesDuringTheHold) {
  const Mission m = localMission({{100, 0, 10}, {100, 100, 10}}, 3.0);
  FlightSettings fs;
  fs.airframe.drag_quadratic_per_m = 0.03;
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{}, fs);
  const StepEvent& e = f.events[1];
  const double leg = e.reached_s - f.events[0].reached_s;
  EXPECT_GT(leg, 16.9);
  EXPECT_LT(leg, 19.0);
  const FlightSample* end = nullptr;
  for (const auto& s : f.samples)
    if (s.t <= e.completed_s) end = &s;
  ASSERT_NE(end, nullptr);
  EXPECT_LT(end->velocity.norm(), 0.2);
  EXPECT_LT((end->position - Eigen::Vector3d(100, 0, 10)).norm(), 0.3);
}

TEST(ArduCopterSCurve, ReturnFromAStopAtHomeTakesTheLoiterAndOneShortLeg) {
  // A square that ends at home (as the SITL square_5mps): the vehicle overshoots the last
  // waypoint by under 1 m (the SITL logs: 0.4-0.9 m), RTL climbs its 1 cm hover offset (1.1 s),
  // flies back from its stopping point (an S-curve of at most 1 m: 3.6 s) and loiters
  // RTL_LOIT_TIME 5 s before landing. ModeRTL::init starts the waypoint controller afresh (AC_WPNav::wp_and_spline_init: the
  // S-curve clock at full speed, the velocity loop's integrator from the lean it holds); carried
  // over from the stop, the slowed clock and the stop's integrator stretched this to about 10 s.
  const Mission m = localMission({{100, 0, 10}, {100, 100, 10}, {0, 100, 10}, {0, 0, 10}});
  FlightSettings fs;
  fs.airframe.drag_linear_per_s = 0.26;
  fs.airframe.drag_quadratic_per_m = 0.03;
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{}, fs);
  double t0 = -1.0, t1 = -1.0;
  for (const auto& s : f.samples) {
    if (s.phase == FlightPhase::Return && t0 < 0.0) t0 = s.t;
    if (s.phase == FlightPhase::Landing && t1 < 0.0) t1 = s.t;
  }
  ASSERT_GT(t0, 0.0);
  ASSERT_GT(t1, t0);
  double overshoot = 0.0;  // [m] past home along the last leg (south)
  for (const auto& s : f.samples) overshoot = std::max(overshoot, -s.position.y());
  EXPECT_LT(overshoot, 1.0);
  EXPECT_GT(t1 - t0, 5.0);
  EXPECT_LT(t1 - t0, 5.0 + 3.6 + 1.1);
}

TEST(ArduCopterSCurve, RtlNearHomeFirstFliesAClimbLegOfTheHoverOffset) {
  // Near home the RTL climb target is the measured altitude, the leg starts at the position target:
  // a hovering vehicle is never on it, and AC_WPNav flies even that leg of centimetres as a whole
  // S-curve. The leg climbs max(vertical tracking error, 1 cm); 1 cm takes 1.1 s and 5 cm 1.6 s
  // with the 4.x defaults (SCurveProfile::restToRest), so the return phase grows by about 0.5 s.
  const Mission m = localMission({{100, 0, 10}, {100, 100, 10}, {0, 100, 10}, {0, 0, 10}});
  auto fly = [&](double vertical) {
    FlightSettings fs;
    fs.sample_dt = fs.dt;
    fs.tracking_error.vertical_m = vertical;
    const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{}, fs);
    double t0 = -1.0, t1 = -1.0, z0 = 0.0, z_top = 0.0;
    for (const auto& s : f.samples) {
      if (s.phase == FlightPhase::Return && t0 < 0.0) t0 = s.t, z0 = s.position.z();
      if (s.phase == FlightPhase::Return) z_top = std::max(z_top, s.position.z());
      if (s.phase == FlightPhase::Landing && t1 < 0.0) t1 = s.t;
    }
    EXPECT_GT(t1, t0);
    return std::make_pair(t1 - t0, z_top - z0);
  };
  const auto [t_1cm, climb_1cm] = fly(0.0);
  const auto [t_5cm, climb_5cm] = fly(0.05);
  EXPECT_NEAR(climb_1cm, 0.01, 0.004);
  EXPECT_NEAR(climb_5cm, 0.05, 0.01);
  const SCurveLimits lim{10.0, 2.5, 1.0, 1.0 * M_PI / (2.0 * 0.15) * 0.5};
  const double extra = SCurveProfile::restToRest(0.05, lim).duration() - SCurveProfile::restToRest(0.01, lim).duration();
  EXPECT_NEAR(t_5cm - t_1cm, extra, 0.25) << "1 cm: " << t_1cm << " s, 5 cm: " << t_5cm << " s";
}

TEST(ArduCopterSCurve, LandingWaitsForTheThrottleToWindDownThenTheDetector) {
  // On the ground the target keeps descending at LAND_SPEED 0.5 m/s: the throttle removed after t s
  // is 0.25 (0.5 (1 + t) + t + t^2 / 2) = 0.125 + 0.375 t + 0.125 t^2 (PSC_POSZ_P 1, PSC_VELZ_P 5,
  // PSC_ACCZ_P 0.5, PSC_ACCZ_I 1). It equals a hover throttle of 0.39 at t = 0.590 s and of 0.2 at
  // t = 0.188 s; the landing detector's 1 s follows either way, so the flights differ by 0.402 s
  // from lift-off (the take-off throttle slew before it also scales with the hover throttle).
  const Mission m = localMission({{30, 0, 10}});
  auto flightTime = [&](double hover) {
    AutopilotConfig ap;
    ap.parameters["MOT_THST_HOVER"] = hover;
    FlightSettings fs;
    fs.sample_dt = fs.dt;
    const FlownMission f = flyMission(sequenceMission(m), ap, fs);
    return f.samples.back().t - liftoffTime(f);
  };
  EXPECT_NEAR(flightTime(0.39) - flightTime(0.2), 0.590 - 0.188, 0.03);
  // A hover throttle the first step already removes (0.1 < 0.125): no wait beyond the detector.
  EXPECT_NEAR(flightTime(0.1) - flightTime(0.2), -0.188, 0.03);
}

TEST(ArduCopterSCurve, VelocityLoopFiltersItsErrorAndAddsTheDerivative) {
  // AC_PID_2D (PSC_VELXY_*): P and I act on the velocity error low-passed at PSC_VELXY_FLTE, D on
  // its rate of change low-passed at PSC_VELXY_FLTD. The filter delays the correction of a lag, so
  // a vehicle with drag behind its S-curve target reaches cruise later with the 5 Hz filter than
  // without (0: off), by less than the filter's time constant 1 / (2 pi 5 Hz) = 0.032 s (the
  // target's own acceleration is fed forward unfiltered); the D term changes the flight too.
  const Mission m = localMission({{200, 0, 10}}, 0.0, 0.0, false);
  FlightSettings fs;
  fs.airframe.drag_linear_per_s = 0.25;
  fs.sample_dt = fs.dt;
  auto reach = [&](double flte, double d) {
    AutopilotConfig ap;
    ap.parameters["PSC_VELXY_FLTE"] = flte;
    ap.parameters["PSC_VELXY_D"] = d;
    const FlownMission f = flyMission(sequenceMission(m), ap, fs);
    for (const auto& s : f.samples)
      if (s.velocity.head<2>().norm() >= 5.0) return s.t;
    return 1e9;
  };
  const double unfiltered = reach(0.0, 0.0), filtered = reach(5.0, 0.0);
  EXPECT_GT(filtered, unfiltered);
  EXPECT_LT(filtered - unfiltered, 1.0 / (2.0 * M_PI * 5.0));
  EXPECT_NE(reach(5.0, 0.25), filtered);
  AutopilotConfig bad;
  bad.parameters["PSC_VELXY_FLTE"] = -1.0;
  try {
    flyMission(sequenceMission(m), bad, fs);
    FAIL() << "a negative filter frequency was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("PSC_VELXY_FLTE"), std::string::npos) << e.what();
  }
}

TEST(ArduCopterSCurve, LeanLimitAndDragCapTheSpeed) {
  const Mission m = localMission({{600, 0, 10}});
  AutopilotConfig ap;
  ap.parameters["WPNAV_SPEED"] = 1500;
  FlightSettings fs;
  fs.airframe.drag_quadratic_per_m = 0.0576;
  const FlownMission f = flyMission(sequenceMission(m), ap, fs);
  double vmax = 0.0;
  for (const auto& s : f.samples) vmax = std::max(vmax, std::hypot(s.velocity.x(), s.velocity.y()));
  EXPECT_NEAR(vmax, std::sqrt(9.80665 * std::tan(M_PI / 6.0) / 0.0576), 0.1);
}


TEST(ArduCopterSCurve, DoChangeSpeedAboveWpnavSpeedIsFlown) {
  // AC_WPNav::set_speed_xy (4.1+) takes any speed of at least WPNAV_WP_SPEED_MIN and passes it to
  // the position controller and the S-curve: nothing caps it at WPNAV_SPEED. A 600 m leg at
  // DO_CHANGE_SPEED 8 m/s with WPNAV_SPEED 5 m/s cruises at 8 m/s (no drag: the lean limit is far).
  const Mission m = localMission({{600, 0, 10}}, 0.0, 8.0);
  AutopilotConfig ap;
  ap.parameters["WPNAV_SPEED"] = 500;
  const FlownMission f = flyMission(sequenceMission(m), ap);
  double vmax = 0.0;
  for (const auto& s : f.samples) vmax = std::max(vmax, std::hypot(s.velocity.x(), s.velocity.y()));
  EXPECT_NEAR(vmax, 8.0, 0.15);
}
TEST(ArduCopterSCurve, ASpeedRaisedAtAWaypointFlownThroughIsASecondAccelerationAfterTheFirst) {
  // ModeAuto::set_next_wp plans the leg after a waypoint flown through when that waypoint starts,
  // at the speed then in force (5 m/s); the DO_CHANGE_SPEED 10 m/s before the next waypoint runs
  // when the first is reached and re-plans that leg in flight (SCurve::set_speed_max): it first
  // reaches 5 m/s, its acceleration falls to 0 there, then it accelerates again to 10 m/s. After a
  // stop the leg is planned after the command: one acceleration from 0 to 10 m/s.
  auto timeNearFiveOnSecondLeg = [](double hold_s) {
    auto steps = sequenceMission(localMission({{200, 0, 10}, {200, 300, 10}}, 0.0));
    steps[1].speed_xy = 5.0;
    steps[1].hold_s = hold_s;
    steps[2].speed_xy = 10.0;
    const FlownMission f = flyMission(steps, AutopilotConfig{});
    double t = 0.0;  // in the first half of the leg, where it accelerates
    const double half = 0.5 * (f.events[1].completed_s + f.events[2].reached_s);
    for (const auto& s : f.samples) {
      const double v = s.velocity.head<2>().norm();
      if (s.t > f.events[1].completed_s + 1.0 && s.t < half && v > 4.5 && v < 5.5) t += f.samples[1].t - f.samples[0].t;
    }
    bool said = false;  // the prediction says so
    for (const auto& n : f.notes) said = said || n.rfind("1 leg(s) after a waypoint flown through are commanded faster", 0) == 0;
    EXPECT_EQ(said, hold_s == 0.0);
    return std::make_pair(t, maxSpeedBetween(f, f.events[1].completed_s, f.events[2].reached_s));
  };
  const auto [through, through_vmax] = timeNearFiveOnSecondLeg(0.0);
  const auto [stop, stop_vmax] = timeNearFiveOnSecondLeg(1.0);
  EXPECT_GT(through, 1.5);  // the join of the two speed changes: |v - 5| < 0.5 m/s for about 2 s
  EXPECT_LT(stop, 0.7);     // one ramp at up to 2.5 m/s^2: about 0.4 s
  EXPECT_NEAR(through_vmax, 10.0, 0.2);
  EXPECT_NEAR(stop_vmax, 10.0, 0.2);
}

TEST(ArduCopterSCurve, TheLeanLagsTheCommandByAtcInputTcUnlessTheAirframeGivesItsResponse) {
  // AC_AttitudeControl::input_shaping_angle follows the lean asked for with gain 1 / ATC_INPUT_TC:
  // without a response in the vehicle file the lean lags by ATC_INPUT_TC (0.15 s by default), and
  // a slower shaping (0.3 s) makes the vehicle lag its target more, so AC_WPNav's clock scaler
  // slows the S-curve and each start from a stop takes longer. A response in the vehicle file wins.
  const auto steps = sequenceMission(localMission({{60, 0, 10}, {60, 60, 10}, {0, 60, 10}}, 1.0));
  auto missionTime = [&](double input_tc, std::optional<double> response) {
    AutopilotConfig ap;
    ap.parameters["ATC_INPUT_TC"] = input_tc;
    FlightSettings fs;
    fs.airframe.drag_linear_per_s = 0.26;
    fs.airframe.drag_quadratic_per_m = 0.03;
    fs.airframe.response_s = response;
    const FlownMission f = flyMission(steps, ap, fs);
    return f.events[3].completed_s - f.events[1].reached_s;
  };
  EXPECT_EQ(missionTime(0.15, std::nullopt), missionTime(0.15, 0.15));
  EXPECT_GT(missionTime(0.3, std::nullopt), missionTime(0.3, 0.15) + 0.1);
  EXPECT_GT(missionTime(0.15, 0.3), missionTime(0.15, std::nullopt) + 0.1);
}

TEST(ArduCopterSCurve, TakeoffClimbsAtWpnavSpeedUpAndLandingEndsOnTheGround) {
  const Mission m = localMission({{0, 50, 10}});
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{});
  // 10 m at 2.5 m/s with 1 m/s^2 and 5 m/s^3: about 10/2.5 + 2.5 + jerk rounding, after 0.5 s spool
  // and the take-off throttle slew to the hover throttle (2 s x 0.35).
  EXPECT_NEAR(f.events[0].reached_s, 0.5 + 0.7 + 6.5, 0.6);
  EXPECT_NEAR(f.samples.back().position.z(), 0.0, 1e-9);
  EXPECT_FALSE(f.samples.back().airborne);
}

// Before lift-off ArduCopter 4.2 and later spools up (MOT_SPOOL_TIME) and then the auto take-off
// slews the throttle up at 1 / TKOFF_SLEW_TIME per second until the vehicle rises at its hover throttle, or at
// TKOFF_THR_MAX (at most 0.9) when that is lower. The SITL quad (MOT_THST_HOVER 0.39) rose 0.78 s
// into the slew (docs/autopilots.md).
TEST(ArduCopterSCurve, LiftOffFollowsTheSpoolUpAndTheTakeoffThrottleSlew) {
  const Mission m = localMission({{30, 0, 10}});
  auto liftoff = [&](double hover, double slew, double thr_max) {
    AutopilotConfig ap;
    ap.parameters["MOT_THST_HOVER"] = hover;
    ap.parameters["TKOFF_SLEW_TIME"] = slew;
    ap.parameters["TKOFF_THR_MAX"] = thr_max;
    FlightSettings fs;
    fs.sample_dt = fs.dt;  // lift-off to the 0.01 s step
    const FlownMission f = flyMission(sequenceMission(m), ap, fs);
    return liftoffTime(f);
  };
  EXPECT_NEAR(liftoff(0.39, 2.0, 0.9), 0.5 + 0.78, 0.015);
  EXPECT_NEAR(liftoff(0.2, 2.0, 0.9), 0.5 + 0.4, 0.015);
  EXPECT_NEAR(liftoff(0.39, 1.0, 0.9), 0.5 + 0.39, 0.015);
  EXPECT_NEAR(liftoff(0.39, 2.0, 0.25), 0.5 + 0.5, 0.015);
  // 4.1 lifts off as the spool-up ends (Mode::auto_takeoff_run had no slew).
  AutopilotConfig ap41 = parseAutopilot(R"({"firmware":"ArduCopter","version":"4.1.5"})", "test");
  FlightSettings fs;
  fs.sample_dt = fs.dt;
  const FlownMission f41 = flyMission(sequenceMission(m), ap41, fs);
  EXPECT_NEAR(liftoffTime(f41), 0.5, 0.015);
}

TEST(Px4, CornerSpeedFollowsTheAcceptanceRadiusFormula) {
  // MPC_XY_TRAJ_P 0.5, MPC_ACC_HOR 3, NAV_ACC_RAD 10 m, 90 deg: sqrt(0.5 * 3 * 10 * tan 45) = 3.87 m/s;
  // at 5 m/s cruise the vehicle is not slowed before the acceptance radius.
  AutopilotConfig px4 = parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test");
  const Mission m = localMission({{100, 0, 10}, {100, 100, 10}});
  const FlownMission f = flyMission(sequenceMission(m), px4);
  const double t = f.events[1].reached_s;
  double v_at_switch = 0.0;
  for (const auto& s : f.samples)
    if (std::abs(s.t - t) < 0.06) v_at_switch = s.velocity.norm();
  EXPECT_NEAR(v_at_switch, 5.0, 0.3);
  EXPECT_GT(minSpeedBetween(f, t, t + 4.0), 2.0);
}

TEST(Px4, TurnKeepsTheSpeedOfBeforeTheTurnUntilHeadedForTheNextLeg) {
  // At 10 m/s into a 90 deg corner the braking law (MPC_ACC_HOR 3, MPC_JERK_AUTO 4) arrives at the
  // 10 m acceptance radius at sqrt(b^2 / 4 + 2 a d + v_c^2) - b / 2 = 5.26 m/s (b = 4 a^2 / j = 9,
  // corner speed v_c = 3.87). PositionSmoothing then keeps that speed while the velocity is more
  // than about 11.5 deg (cos 0.98) off the direction to its target, aimed at the L1 point 10 m
  // ahead on the next leg's line, and speeds up to 10 m/s only once headed along it.
  AutopilotConfig px4 = parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test");
  const Mission m = localMission({{100, 0, 10}, {100, 200, 10}}, 0.0, 10.0);
  const FlownMission f = flyMission(sequenceMission(m), px4);
  const double t_switch = f.events[1].reached_s;  // steps: take-off, WP1, WP2, RTL
  double v_switch = -1.0, t_aligned = -1.0, cross_after = 0.0;
  for (const auto& s : f.samples) {
    if (s.t < t_switch - 1e-9) continue;
    const Eigen::Vector2d vh = s.velocity.head<2>();
    if (v_switch < 0.0) v_switch = vh.norm();
    if (t_aligned < 0.0 && vh.norm() > 0.2 && vh.normalized().y() >= 0.98) t_aligned = s.t;
    if (t_aligned < 0.0) {
      EXPECT_LE(vh.norm(), v_switch + 0.05) << "at " << s.t;
    }
    if (s.phase == FlightPhase::Mission && s.position.y() > 30.0 && s.position.y() < 150.0) cross_after = std::max(cross_after, std::abs(s.position.x() - 100.0));
  }
  EXPECT_GE(v_switch, 5.26);  // the jerk-limited trajectory runs a little behind the braking law
  EXPECT_LT(v_switch, 5.8);
  ASSERT_GT(t_aligned, t_switch);
  EXPECT_GT(maxSpeedBetween(f, t_aligned, t_aligned + 6.0), 9.5);  // then up to the cruise speed
  // Within 1.5 m of the next leg's line: the L1 point brings the turn onto it, then the vehicle
  // heads for the waypoint itself (the ArduCopter-like cut straight to it would be far off).
  EXPECT_LT(cross_after, 1.5);
}

TEST(Px4, DiagonalLegsAxesReachTheirSpeedsTogether) {
  // A leg at 30 deg from rest: east needs 4.33 m/s and north 2.5 m/s. Each axis alone would take
  // V / A + A / J: 2.19 s east, 1.58 s north (MPC_ACC_HOR 3, MPC_JERK_AUTO 4). VelocitySmoothing's
  // time synchronisation re-plans the north axis to the east one's length, so both reach their
  // speeds together, as in PX4 (both start at the same jerk, so the velocity first points at
  // 45 deg and turns to 30 deg as it grows).
  AutopilotConfig px4 = parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test");
  const double c = std::cos(M_PI / 6.0), sn = std::sin(M_PI / 6.0);
  const FlownMission f = flyMission(sequenceMission(localMission({{300 * c, 300 * sn, 10}})), px4);
  double start = -1.0, east = -1.0, north = -1.0;
  for (const auto& s : f.samples) {
    if (s.phase != FlightPhase::Mission) continue;
    if (start < 0.0 && s.velocity.head<2>().norm() > 0.01) start = s.t;
    if (east < 0.0 && s.velocity.x() >= 0.99 * 5.0 * c) east = s.t;
    if (north < 0.0 && s.velocity.y() >= 0.99 * 5.0 * sn) north = s.t;
  }
  ASSERT_GT(start, 0.0);
  EXPECT_NEAR(east - start, 5.0 * c / 3.0 + 0.75, 0.3);
  EXPECT_NEAR(north, east, 0.15);
}

TEST(Px4, StraightLegAccelerationTakesVOverAPlusAOverJ) {
  AutopilotConfig px4 = parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test");
  const Mission m = localMission({{300, 0, 10}}, 1.0);
  const FlownMission f = flyMission(sequenceMission(m), px4);
  // Find when the speed first reaches 99 % of 5 m/s after the take-off: about V/A + A/J = 2.42 s.
  const double t0 = f.events[0].completed_s;
  double t99 = 0.0;
  for (const auto& s : f.samples)
    if (s.t > t0 && s.velocity.head<2>().norm() >= 0.99 * 5.0) {
      t99 = s.t - t0;
      break;
    }
  EXPECT_NEAR(t99, 5.0 / 3.0 + 3.0 / 4.0, 0.5);
}

// PX4's take-off climbs at MPC_TKO_SPEED (1.5 m/s) below MPC_LAND_ALT1 (10 m) and at
// MPC_Z_V_AUTO_UP (3 m/s) above it (FlightTaskAuto::_updateTrajConstraints).
TEST(Px4, TakeoffClimbsAtTheTakeoffSpeedBelowLandAlt1AndFasterAbove) {
  const AutopilotConfig px4 = parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test");
  const FlownMission f = flyMission(sequenceMission(localMission({{100, 0, 40}})), px4);
  double below = 0.0, above = 0.0;
  for (const auto& s : f.samples) {
    if (s.phase != FlightPhase::Takeoff) continue;
    (s.position.z() < 9.0 ? below : above) = std::max(s.position.z() < 9.0 ? below : above, s.velocity.z());
  }
  EXPECT_NEAR(below, 1.5, 0.05);
  EXPECT_NEAR(above, 3.0, 0.05);
  // Worked by hand with PX4's own laws (1.14 defaults): the 1 s spool-up; 0 -> 1.5 m/s at
  // MPC_TKO_SPEED / MPC_TKO_RAMP_T = 0.5 m/s^2 with jerk 4 (3.125 s, 2.34 m); 1.5 m/s to 10 m
  // (5.10 s); 1.5 -> 3 m/s with jerk 4 (1.22 s, 2.76 m); 3 m/s until the braking law
  // v^2 + (4 a^2 / j) v = 2 a d (a = MPC_ACC_UP_MAX 4, j 4) falls below 3 m/s, 7.125 m below the
  // top (6.71 s); then along that law, t = dv / a + (b / 2a) ln(v1 / v0) with b = 16, from 3 m/s
  // to its 0.39 m/s at 0.8 m (NAV_MC_ALT_RAD) below 40 m, where the take-off counts as reached
  // (4.73 s): 21.9 s, where 40 m at 1.5 m/s would take 27 s.
  EXPECT_NEAR(f.events[0].reached_s, 21.9, 0.3);
}

// PX4's land law by version, landing from 10 m with MPC_LAND_ALT1 12 m, MPC_LAND_ALT2 6 m,
// MPC_LAND_SPEED 0.7 m/s, MPC_Z_VEL_MAX_DN 1.5 m/s. Before 1.11 (FlightTaskAutoMapper2) the
// descent is at 0.7 m/s below ALT1: 10 / 0.7 = 14.29 s. From 1.11 it is graded between ALT2 and
// ALT1, v(h) = 0.7 + 0.8 (h - 6) / 6: 7.5 ln(1.233 / 0.7) + 6 / 0.7 = 4.25 + 8.57 = 12.82 s, 1.47 s
// less; it starts at 1.23 m/s, whose ramp at MPC_ACC_DOWN_MAX (3 m/s^2) loses v / 2a = 0.21 s
// against 0.12 s: 1.38 s less in all (the 0.1 s samples bound the start and the touch-down).
TEST(Px4, Before111LandsAtLandSpeedBelowLandAlt1AndGradesFromAlt2Since) {
  auto landing = [](const std::string& version) {
    const AutopilotConfig px4 = parseAutopilot(R"({"firmware":"PX4","version":")" + version +
                                                   R"(","parameters":{"MPC_LAND_ALT1":12,"MPC_LAND_ALT2":6}})", "test");
    Mission m = localMission({{5, 0, 10}}, 0.0, 0.0, false);
    MissionItem land = m.items.back();
    land.seq += 1;
    land.command = 21;
    land.lat_deg = land.lon_deg = 0.0;  // land where the vehicle is
    land.alt_m = 0.0;
    m.items.push_back(land);
    const FlownMission f = flyMission(sequenceMission(m), px4);
    double start = -1.0, down = -1.0, fastest = 0.0;
    for (const auto& s : f.samples) {
      if (s.phase != FlightPhase::Landing) continue;
      if (start < 0.0 && s.velocity.z() < -0.01) start = s.t;
      if (down < 0.0 && s.position.z() <= 0.0) down = s.t;
      fastest = std::max(fastest, -s.velocity.z());
    }
    return std::make_pair(down - start, fastest);
  };
  const auto old_law = landing("1.10.2"), new_law = landing("1.14.0");
  EXPECT_NEAR(old_law.second, 0.7, 0.01);
  // From 1.11 the law asks for 1.233 m/s at 10 m (graded between ALT2 6 m and ALT1 12 m); the
  // jerk-limited descent (MPC_JERK_AUTO 4) meets the falling law a little below that.
  EXPECT_LE(new_law.second, 1.233 + 0.005);
  EXPECT_GT(new_law.second, 1.1);
  EXPECT_NEAR(old_law.first - new_law.first, 1.38, 0.2);
}

// PX4's RTL turns to the heading the vehicle armed with before it lands, which a mission file does
// not give: the prediction says how long that may take, (180 - MIS_YAW_ERR) / MPC_YAWRAUTO_MAX =
// (180 - 12) / 45 = 3.73 s with the defaults.
TEST(Px4, ReturnSaysTheHeadingTurnItLeavesOut) {
  const AutopilotConfig px4 = parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test");
  const FlownMission f = flyMission(sequenceMission(localMission({{50, 0, 10}})), px4);
  EXPECT_TRUE(std::any_of(f.notes.begin(), f.notes.end(),
                          [](const std::string& n) { return n.find("up to 3.733 s of hover") != std::string::npos; }));
  const FlownMission no_rtl = flyMission(sequenceMission(localMission({{50, 0, 10}}, 0.0, 0.0, false)), px4);
  EXPECT_TRUE(std::none_of(no_rtl.notes.begin(), no_rtl.notes.end(),
                           [](const std::string& n) { return n.find("heading the vehicle armed with") != std::string::npos; }));
}

// PX4's navigator takes every DO_CHANGE_SPEED's param2 as the cruise speed, whatever the speed type
// in param1 (even a climb speed), returns to MPC_XY_CRUISE on -1 (ArduPilot: no change), and RTL
// starts at MPC_XY_CRUISE again (RtlDirect::on_activation resets it).
TEST(Px4, ChangeSpeedSetsTheCruiseWhateverItsTypeMinusOneAndRtlReturnToTheDefault) {
  const AutopilotConfig px4 = parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test");
  // Take-off, DO_CHANGE_SPEED 8 m/s, 300 m east, DO_CHANGE_SPEED (type, speed), 300 m north, RTL.
  auto peaks = [&](double type, double speed) {
    Mission m = localMission({{300, 0, 10}, {300, 300, 10}}, 0.0, 8.0);
    MissionItem change = m.items[1];  // the DO_CHANGE_SPEED localMission wrote
    change.param[0] = type;
    change.param[1] = speed;
    m.items.insert(m.items.begin() + 3, change);
    for (std::size_t i = 0; i < m.items.size(); ++i) m.items[i].seq = static_cast<int>(i) + 1;
    const FlownMission f = flyMission(sequenceMission(m), px4);
    double second = 0.0, rtl = 0.0;
    for (const auto& s : f.samples) {
      const double v = s.velocity.head<2>().norm();
      if (s.phase == FlightPhase::Mission && s.position.y() > 50 && s.position.y() < 250) second = std::max(second, v);
      if (s.phase == FlightPhase::Return) rtl = std::max(rtl, v);
    }
    return std::make_pair(second, rtl);
  };
  EXPECT_NEAR(peaks(1, 6).first, 6.0, 0.05);   // a ground speed
  EXPECT_NEAR(peaks(2, 3).first, 3.0, 0.05);   // a climb speed sets the cruise too
  EXPECT_NEAR(peaks(1, -1).first, 5.0, 0.05);  // back to MPC_XY_CRUISE
  EXPECT_NEAR(peaks(1, 6).second, 5.0, 0.05);  // RTL at MPC_XY_CRUISE
}

// The height RTL returns at, from PX4's navigator (RTL::computeReturnAltitude, 1.13 on; the rule
// before it for 1.10-1.12; none before the cone), with the defaults RTL_RETURN_ALT 60 m, RTL_CONE_ANG 45 deg, RTL_MIN_DIST
// 10 m, NAV_ACC_RAD 10 m, RTL_DESCEND_ALT 30 m. The last waypoint, at 10 m, is reached within
// 0.5 m (its param2), so RTL starts up to 0.5 m short of it: heights that follow the distance
// are expected within 1 m.
TEST(Px4, RtlClimbsToTheReturnAltitudeOfItsVersion) {
  const auto returnHeight = [](const std::string& version, double x, const std::string& parameters = "{}") {
    const AutopilotConfig px4 =
        parseAutopilot(R"({"firmware":"PX4","version":")" + version + R"(","parameters":)" + parameters + "}", "test");
    Mission m = localMission({{x, 0, 10}});
    m.items[1].param[1] = 0.5;  // acceptance radius of the waypoint
    const FlownMission f = flyMission(sequenceMission(m), px4);
    double top = 0.0;
    for (const auto& s : f.samples)
      if (s.phase == FlightPhase::Return) top = std::max(top, s.position.z());
    return top;
  };
  // Where the vehicle is when the RTL starts (the return altitude is the navigator's of that point):
  // the waypoint x m out is reached 0.5 m short of it.
  const auto startDistance = [](double x) {
    const AutopilotConfig px4 = parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test");
    Mission m = localMission({{x, 0, 10}});
    m.items[1].param[1] = 0.5;
    const FlownMission f = flyMission(sequenceMission(m), px4);
    for (const auto& s : f.samples)
      if (s.phase == FlightPhase::Return) return s.position.head<2>().norm();
    return std::nan("");
  };
  const double d8 = startDistance(8.0);
  EXPECT_NEAR(d8, 7.5, 0.1);
  // 1.14 beyond RTL_MIN_DIST: RTL_RETURN_ALT.
  EXPECT_NEAR(returnHeight("1.14", 200), 60.0, 0.5);
  // The climb ends within NAV_MC_ALT_RAD (0.8 m) of the return altitude (the navigator's item is
  // reached); when home is within NAV_ACC_RAD the landing follows at once, else the return leg
  // climbs on towards that altitude. So the top is within 0.8 m below it (0.9 m with the last
  // 0.1 s sample at about 0.5 m/s), never above.
  const auto expectReturnAltitude = [](double top, double alt) {
    EXPECT_LE(top, alt + 0.01);
    EXPECT_GE(top, alt - 0.9);
  };
  // 1.14, 8 m out, within NAV_ACC_RAD: twice the distance.
  expectReturnAltitude(returnHeight("1.14", 8), 2.0 * d8);
  // 1.14, 8 m out with NAV_ACC_RAD 1 m: the 30 deg cone's d / tan 30 (13.0 m; within RTL_MIN_DIST).
  expectReturnAltitude(returnHeight("1.14", 8, R"({"NAV_ACC_RAD":1,"RTL_CONE_ANG":30})"), d8 / std::tan(M_PI / 6.0));
  // ... the 45 deg cone's 8 m is below the vehicle, which returns at its 10 m.
  EXPECT_NEAR(returnHeight("1.14", 8, R"({"NAV_ACC_RAD":1})"), 10.0, 0.5);
  // 1.12: the 45 deg cone at any distance, capped at RTL_RETURN_ALT; within RTL_MIN_DIST, RTL_DESCEND_ALT.
  EXPECT_NEAR(returnHeight("1.12", 40), 40.0, 1.0);
  EXPECT_NEAR(returnHeight("1.12", 200), 60.0, 0.5);
  expectReturnAltitude(returnHeight("1.12", 8), 30.0);
  // 1.9 had no cone (its logs carry no RTL_CONE_ANG): RTL_RETURN_ALT.
  EXPECT_NEAR(returnHeight("1.9.0", 40), 60.0, 0.5);
}

TEST(ArduCopterLeash, StopWaypointIsReachedWithinTheRadiusAndHoldsStill) {
  AutopilotConfig ac3 = parseAutopilot(R"({"firmware":"ArduCopter","version":"3.3.3"})", "test");
  ASSERT_EQ(ac3.family, AutopilotFamily::ArduCopterLeash);
  const Mission m = localMission({{100, 0, 10}}, 5.0);
  const FlownMission f = flyMission(sequenceMission(m), ac3);
  const StepEvent& e = f.events[1];
  // 100 m at WPNAV_SPEED 5 m/s with WPNAV_ACCEL 1 m/s^2: longer than 20 s at constant speed, shorter
  // than a triangular profile at half the acceleration.
  const double leg = e.reached_s - f.events[0].completed_s;
  EXPECT_GT(leg, 20.0);
  EXPECT_LT(leg, 35.0);
  for (const auto& s : f.samples) {
    if (s.t > e.reached_s && s.t < e.completed_s) {
      EXPECT_LT((s.position - Eigen::Vector3d(100, 0, 10)).norm(), 2.5);
    }
  }
}

TEST(ArduCopterLeash, LandingWaitsForTheThrottleToWindDownUnder32Names) {
  // ArduCopter 3.2: hover throttle THR_MID / 1000, the vertical gains THR_RATE_P, THR_ACCEL_P and
  // _I. With the defaults (500, 5, 0.5, 1) the throttle removed after touch-down,
  // 0.125 + 0.375 t + 0.125 t^2, reaches 0.5 at t = 0.791 s; THR_MID 300 at 0.411 s. The IRIS+
  // frame file's THR_ACCEL_I 1.5 (3.2 name) gives 0.125 + 0.5 t + 0.1875 t^2 = 0.5 at 0.610 s.
  const Mission m = localMission({{30, 0, 10}});
  auto flightTime = [&](const std::map<std::string, double>& params) {
    AutopilotConfig ap;
    ap.family = AutopilotFamily::ArduCopterLeash;
    ap.version = "3.2";
    ap.parameters = params;
    FlightSettings fs;
    fs.sample_dt = fs.dt;
    return flyMission(sequenceMission(m), ap, fs).samples.back().t;
  };
  const double base = flightTime({});
  EXPECT_NEAR(base - flightTime({{"THR_MID", 300}}), 0.791 - 0.411, 0.03);
  EXPECT_NEAR(base - flightTime({{"THR_ACCEL_I", 1.5}}), 0.791 - 0.610, 0.03);
  EXPECT_NEAR(base - flightTime({{"MOT_THST_HOVER", 0.3}}), 0.791 - 0.411, 0.03);  // 3.4 and later
}

TEST(ArduCopterLeash, SpeedIncreaseTakesEffectOneWaypointLateADecreaseAtOnce) {
  // AC_WPNav 3.x computes a leg's track leash from the position controller's leash before that
  // controller has applied the DO_CHANGE_SPEED run just before the leg: the carrot cannot run
  // further ahead than the old speed's leash, which the square-root controller turns into the old
  // speed; a decrease is capped by the position controller at once.
  const AutopilotConfig ac3 = parseAutopilot(R"({"firmware":"ArduCopter","version":"3.3"})", "test");
  auto steps = sequenceMission(localMission({{200, 0, 10}, {400, 0, 10}, {600, 0, 10}, {800, 0, 10}}));
  ASSERT_EQ(steps.size(), 6u);
  steps[1].speed_xy = steps[1].speed_xy_3x = 3.0;  // 3 m/s from the take-off point
  steps[2].speed_xy = steps[2].speed_xy_3x = 8.0;  // raised before the second leg: flown at 3 m/s
  steps[3].speed_xy = steps[3].speed_xy_3x = 8.0;  // the third leg flies 8 m/s
  steps[4].speed_xy = steps[4].speed_xy_3x = 2.0;  // lowered before the fourth leg: 2 m/s at once
  const FlownMission f = flyMission(steps, ac3);
  const auto& e = f.events;
  EXPECT_LT(maxSpeedBetween(f, e[1].reached_s, e[2].reached_s), 3.3);
  EXPECT_GT(maxSpeedBetween(f, e[2].reached_s, e[3].reached_s), 7.5);
  EXPECT_LT(maxSpeedBetween(f, e[3].reached_s + 20.0, e[4].reached_s), 2.1);
  // The prediction says so: one leg (the second) commanded faster than the one before.
  bool said = false;
  for (const auto& n : f.notes) said = said || n.rfind("1 leg(s) are commanded faster than the leg before", 0) == 0;
  EXPECT_TRUE(said);
}

// Copter::do_change_speed of 3.2-3.6 reads param2 only: a DO_CHANGE_SPEED of type 2 (climb) sets
// the horizontal speed, in the mission and in RTL (WPNAV_SPEED overwritten in memory). The type
// check came with ArduPilot PR 9535 (October 2018): 4.0 leaves the horizontal speed alone, and the
// prediction says it does not follow the climb speed. Types 2 and 3 had no effect on 3.x before.
TEST(ArduCopterLeash, ClimbOrDescentSpeedSetsTheHorizontalSpeedBefore40) {
  Mission m = localMission({{300, 0, 10}}, 0.0, 3.0);
  m.items[1].param[0] = 2.0;  // DO_CHANGE_SPEED type 2 (climb), 3 m/s
  for (const char* version : {"3.3", "3.6"}) {
    const AutopilotConfig ac3 = parseAutopilot(std::string(R"({"firmware":"ArduCopter","version":")") + version + "\"}", "test");
    const FlownMission f = flyMission(sequenceMission(m), ac3);
    EXPECT_LT(maxSpeedBetween(f, f.events[1].completed_s, f.events[2].reached_s), 3.1) << version;
    double rtl = 0.0;
    for (const auto& s : f.samples)
      if (s.phase == FlightPhase::Return) rtl = std::max(rtl, s.velocity.head<2>().norm());
    EXPECT_LT(rtl, 3.1) << version;  // RTL at the speed in memory
  }
  const AutopilotConfig ac40 = parseAutopilot(R"({"firmware":"ArduCopter","version":"4.0.7"})", "test");
  ASSERT_EQ(ac40.family, AutopilotFamily::ArduCopterLeash);
  const FlownMission f = flyMission(sequenceMission(m), ac40);
  EXPECT_GT(maxSpeedBetween(f, f.events[1].completed_s, f.events[2].reached_s), 4.5);  // WPNAV_SPEED 5 m/s
  EXPECT_TRUE(std::any_of(f.notes.begin(), f.notes.end(), [](const std::string& n) {
    return n.find("a DO_CHANGE_SPEED of type 2 or 3 (climb or descent): ArduCopter 4.0.7 sets WPNAV's climb") != std::string::npos;
  }));
}

// predict --json's reached_s of NAV_RETURN_TO_LAUNCH is when the vehicle is over home (before the
// loiter and the descent) in every model: the S-curve model gave the end of the return climb, 300 m
// from home, and PX4's the end of RTL_LAND_DELAY.
TEST(Sequence, TheReturnIsReachedOverHomeInEveryModel) {
  const Mission m = localMission({{300, 0, 10}});
  for (const char* ap : {R"({"firmware":"ArduCopter","version":"4.5"})", R"({"firmware":"ArduCopter","version":"3.3"})",
                         R"({"firmware":"PX4","version":"1.14","parameters":{"RTL_LAND_DELAY":3}})"}) {
    const AutopilotConfig a = parseAutopilot(ap, "test");
    const FlownMission f = flyMission(sequenceMission(m), a);
    const StepEvent& rtl = f.events.back();
    ASSERT_TRUE(std::isfinite(rtl.reached_s)) << ap;
    const auto at = std::min_element(f.samples.begin(), f.samples.end(), [&](const FlightSample& x, const FlightSample& y) {
      return std::abs(x.t - rtl.reached_s) < std::abs(y.t - rtl.reached_s);
    });
    EXPECT_LT(at->position.head<2>().norm(), 10.5) << ap;  // within NAV_ACC_RAD (PX4) or WPNAV_RADIUS of home
    EXPECT_GT(at->position.z(), 5.0) << ap;                 // not yet landed
    EXPECT_LT(rtl.reached_s, rtl.completed_s - 3.0) << ap;  // the loiter or delay and the descent follow
  }
}

// Mean horizontal speed [m/s] of the samples between x0 and x1 [m] east.
double cruiseSpeedBetween(const FlownMission& f, double x0, double x1) {
  double sum = 0.0;
  int n = 0;
  for (const auto& s : f.samples)
    if (s.position.x() >= x0 && s.position.x() <= x1 && s.position.z() > 9.0) sum += s.velocity.head<2>().norm(), ++n;
  return n > 0 ? sum / n : 0.0;
}

TEST(ArduCopterLeash, ATrackingErrorSlowsTheCruiseBefore34AsTheLeashSlackSays) {
  // Hand-worked (WPNAV_SPEED 5 m/s, WPNAV_ACCEL 1 m/s^2, POS_XY_P 1/s): the leash is
  // A / (2 kP^2) + V^2 / (2 A) = 13 m, and in cruise the carrot runs a leash ahead, where the
  // square-root controller asks sqrt(2 A (13 - 0.5)) = 5 m/s. Before 3.4 the slack is the leash
  // minus the cross-track error: 1 m off the line leaves 12 m, sqrt(2 (12 - 0.5)) = 4.80 m/s. A
  // vertical 0.3 m, above the line as often as below, counts against the 3.625 m climb and the
  // 1.625 m descent leash: 13 x 0.3 x (1 / 3.625 + 1 / 1.625) / 2 = 1.74 m, sqrt(2 (11.26 - 0.5)) = 4.64 m/s.
  // From 3.4 the slack is sqrt(13^2 - 1^2) = 12.96 m: 4.99 m/s. Before 3.4 the carrot moves only
  // every 0.1 s (update_wpnav at 10 Hz), so between its moves the vehicle closes in by up to one
  // step (0.5 m at 5 m/s): up to half a step less lead on average, sqrt(2 A) x 0.25 m / v, about
  // 0.05 m/s slower than the continuous figures above (0.06 allowed).
  const auto steps = sequenceMission(localMission({{400, 0, 10}}));
  const AutopilotConfig v32 = parseAutopilot(R"({"firmware":"ArduCopter","version":"3.2"})", "test");
  const AutopilotConfig v34 = parseAutopilot(R"({"firmware":"ArduCopter","version":"3.4"})", "test");
  FlightSettings off;
  off.tracking_error.horizontal_m = 1.0;
  const auto f = flyMission(steps, v32);
  const double on_line = cruiseSpeedBetween(f, 150, 300), off_line = cruiseSpeedBetween(flyMission(steps, v32, off), 150, 300);
  EXPECT_GE(on_line, 4.94);
  EXPECT_LE(on_line, 5.0 + 1e-9);
  EXPECT_GE(off_line, 4.74);
  EXPECT_LE(off_line, 4.80);
  EXPECT_NEAR(on_line - off_line, 5.0 - 4.80, 0.03);  // the tracking error's own share, as hand-worked
  EXPECT_NEAR(cruiseSpeedBetween(flyMission(steps, v34, off), 150, 300), 4.99, 0.03);
  FlightSettings high;
  high.tracking_error.vertical_m = 0.3;
  const double high_line = cruiseSpeedBetween(flyMission(steps, v32, high), 150, 300);
  EXPECT_GE(high_line, 4.58);
  EXPECT_LE(high_line, 4.64);
  // The prediction says what it assumed.
  bool said = false;
  for (const auto& n : flyMission(steps, v32, off).notes) said = said || n.find("1 m off its line horizontally") != std::string::npos;
  EXPECT_TRUE(said);
  // Out of range is an error naming the field.
  off.tracking_error.horizontal_m = -0.1;
  try {
    flyMission(steps, v32, off);
    FAIL() << "a negative tracking error was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("tracking_error"), std::string::npos) << e.what();
  }
}

TEST(ArduCopterLeash, ASimulationStepThatDoesNotDivideTheTenthSecondFliesAlike) {
  // Before 3.4 the carrot and the position controller run every 0.1 s, over the time that passed:
  // with steps of 0.03 or 0.04 s (every 0.12 s) the flight is the one at 0.01 s, to a tenth of a
  // metre per second in cruise and a percent in time. (Stepped by a fixed 0.1 s, the carrot ran at
  // 0.1 / 0.12 of its speed: 4.17 m/s cruise instead of 4.94.)
  const auto steps = sequenceMission(localMission({{400, 0, 10}, {400, 200, 10}}));
  const AutopilotConfig v32 = parseAutopilot(R"({"firmware":"ArduCopter","version":"3.2"})", "test");
  const FlownMission fine = flyMission(steps, v32);
  for (const double dt : {0.03, 0.04}) {
    FlightSettings s;
    s.dt = dt;
    s.sample_dt = 0.12;
    const FlownMission coarse = flyMission(steps, v32, s);
    EXPECT_NEAR(cruiseSpeedBetween(coarse, 150, 300), cruiseSpeedBetween(fine, 150, 300), 0.1) << dt;
    EXPECT_NEAR(coarse.samples.back().t / fine.samples.back().t, 1.0, 0.01) << dt;
  }
}

TEST(ArduCopterLeash, Before34OneTenthSecondClockDrivesTheCarrotAcrossLegs) {
  // AC_WPNav::update_wpnav (3.2) moves the carrot when 0.1 s have passed since it last did, whatever
  // leg it is on: a new leg's carrot first moves at the next tick, not at once. A fast waypoint is
  // reached at a carrot move, so every waypoint of the flight is reached on one 0.1 s grid. (With a
  // clock restarted at each leg, each reach came one simulation step later on the grid.)
  const auto steps = sequenceMission(localMission({{60, 0, 10}, {60, 40, 10}, {20, 40, 10}, {20, 90, 10}, {90, 90, 10}}));
  const AutopilotConfig v32 = parseAutopilot(R"({"firmware":"ArduCopter","version":"3.2"})", "test");
  const FlownMission f = flyMission(steps, v32);
  std::vector<double> reached;
  for (std::size_t k = 1; k + 1 < steps.size(); ++k)
    if (steps[k].kind == NavStep::Kind::Waypoint) reached.push_back(f.events[k].reached_s);
  ASSERT_GE(reached.size(), 4u);
  for (std::size_t k = 1; k < reached.size(); ++k) {
    const double ticks = (reached[k] - reached[0]) / 0.1;
    EXPECT_NEAR(ticks, std::round(ticks), 1e-6) << "waypoint " << k << " reached " << reached[k] - reached[0] << " s after the first";
  }
}

TEST(ArduCopterLeash, ReturnFromAboveRtlAltFliesHomeAndLands) {
  // Above RTL_ALT (15 m) the RTL climb leg is (nearly) zero long; it used to wait for a carrot
  // that never moves until the 6 h limit.
  const AutopilotConfig ac3 = parseAutopilot(R"({"firmware":"ArduCopter","version":"3.3"})", "test");
  const FlownMission f = flyMission(sequenceMission(localMission({{100, 100, 40}})), ac3);
  EXPECT_LT(f.samples.back().t, 300.0);
  EXPECT_LT(f.samples.back().position.head<2>().norm(), 2.5);
  EXPECT_NEAR(f.samples.back().position.z(), 0.0, 1e-9);
}

TEST(Sequence, DoChangeSpeedGovernsTheNextLegAndBadSpeedsAreErrors) {
  Mission m = localMission({{100, 0, 10}}, 0.0, 4.0);
  const auto steps = sequenceMission(m);
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[1].speed_xy, 4.0);
  m.items[1].param[1] = 0.0;
  try {
    sequenceMission(m);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("DO_CHANGE_SPEED speed (param2) = 0"), std::string::npos) << e.what();
  }
}

TEST(Sequence, DoJumpLoopsAreBoundedAndUnrolled) {
  Mission m = localMission({{50, 0, 10}, {50, 50, 10}}, 0.0, 0.0, false);
  MissionItem jump;
  jump.seq = 4;
  jump.command = 177;
  jump.frame = 2;
  jump.param[0] = 2;  // back to the first waypoint
  jump.param[1] = 3;  // three more times
  jump.where = "test item 4";
  m.items.push_back(jump);
  std::vector<std::string> w;
  const auto steps = sequenceMission(m, &w);
  EXPECT_EQ(steps.size(), 1u + 2u * 4u);
  jump.param[1] = -1;
  m.items.back() = jump;
  EXPECT_THROW(sequenceMission(m), std::invalid_argument);
}

TEST(Autopilot, FamiliesFollowFirmwareAndVersion) {
  EXPECT_EQ(familyOf("ArduCopter", "4.0.7"), AutopilotFamily::ArduCopterLeash);
  EXPECT_EQ(familyOf("ArduCopter", "V4.1.0"), AutopilotFamily::ArduCopterSCurve);
  EXPECT_EQ(familyOf("PX4", "v1.15.0"), AutopilotFamily::PX4);
  EXPECT_THROW(familyOf("ArduPlane", "4.5"), std::invalid_argument);
  EXPECT_THROW(parseAutopilot(R"({"firmware":"ArduCopter","version":"4.5","parameters":{"WPNAV_SPEED":"fast"}})", "v.json"),
               std::invalid_argument);
  const AutopilotConfig c = parseAutopilot(R"({"firmware":"ArduCopter","version":"4.5","parameters":{"WPNAV_SPEED":500}})", "v");
  EXPECT_EQ(c.get("WPNAV_SPEED"), 500);
  EXPECT_EQ(c.get("WPNAV_ACCEL"), 250);  // documented default
  EXPECT_THROW(c.get("NO_SUCH_PARAM"), std::out_of_range);
}

TEST(FlightPieces, PiecesKeepTheTrajectoryTimeAndLength) {
  const Mission m = localMission({{100, 0, 10}, {100, 100, 10}});
  const FlownMission f = flyMission(sequenceMission(m), AutopilotConfig{});
  const FlightPieces p = toPieces(f);
  double t = 0.0, path = 0.0;
  for (const auto& pc : p.pieces) t += pc.duration;
  for (std::size_t i = 1; i < f.samples.size(); ++i) path += (f.samples[i].position - f.samples[i - 1].position).norm();
  EXPECT_NEAR(t, f.samples.back().t, 1e-9);
  double len = 0.0;
  for (const auto& pc : p.pieces) len += pc.length;
  EXPECT_NEAR(len, path, 0.01 * path);
}
