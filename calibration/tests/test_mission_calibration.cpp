// Mission calibration's measuring tools on hand-made trajectories: the track alignment recovers a
// known shift, passages and leg times of a constant-speed track are exact, unmatched waypoints are
// NaN, never a guess.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "test_util.hpp"
#include "wattswath/calibration/mission_calibration.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/mission/flight.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/predict.hpp"

using namespace wattswath::calibration;

namespace {

// A square flown at 5 m/s sampled at 10 Hz, 10 m up, shifted by `shift`.
void square(const Eigen::Vector2d& shift, std::vector<double>& t, std::vector<Eigen::Vector3d>& pos, std::vector<double>& power) {
  const std::vector<Eigen::Vector2d> corners = {{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 0}};
  double time = 0.0;
  for (std::size_t c = 1; c < corners.size(); ++c) {
    for (double s = 0.0; s < 100.0; s += 0.5) {
      const Eigen::Vector2d p = corners[c - 1] + (corners[c] - corners[c - 1]) * (s / 100.0) + shift;
      t.push_back(time);
      pos.emplace_back(p.x(), p.y(), 10.0);
      power.push_back(200.0);
      time += 0.1;
    }
  }
}

std::vector<Eigen::Vector3d> waypoints() { return {{100, 0, 10}, {100, 100, 10}, {0, 100, 10}, {0, 0, 10}}; }

}  // namespace

TEST(MissionCalibration, AlignmentRecoversAKnownShift) {
  std::vector<double> t, power;
  std::vector<Eigen::Vector3d> pos;
  square({7.3, -4.1}, t, pos, power);
  const Eigen::Vector2d d = alignTrack(pos, waypoints());
  EXPECT_NEAR(d.x(), 7.3, 0.11);
  EXPECT_NEAR(d.y(), -4.1, 0.11);
}

TEST(MissionCalibration, ConstantSpeedTrackGivesExactLegTimesAndEnergy) {
  std::vector<double> t, power;
  std::vector<Eigen::Vector3d> pos;
  square({0, 0}, t, pos, power);
  const FlightTimes ft = flightTimes(t, pos, power, waypoints());
  ASSERT_EQ(ft.leg_s.size(), 3u);
  for (double l : ft.leg_s) EXPECT_NEAR(l, 20.0, 0.11);
  for (double v : ft.leg_speed_mps) EXPECT_NEAR(v, 5.0, 0.05);
  for (double e : ft.leg_energy_j) EXPECT_NEAR(e, 200.0 * 20.0, 25.0);
  // Every leg peaks at 5 m/s and nothing is slow (a corner's 1 s chord is 3.5 m).
  ASSERT_EQ(ft.leg_peak_mps.size(), 3u);
  for (double v : ft.leg_peak_mps) EXPECT_NEAR(v, 5.0, 1e-9);
  EXPECT_NEAR(ft.slow_s, 0.0, 1e-9);
  EXPECT_NEAR(ft.energy_j, 200.0 * t.back(), 1e-6);
}

TEST(MissionCalibration, WaypointTheTrackNeverComesNearIsNotMatched) {
  std::vector<double> t, power;
  std::vector<Eigen::Vector3d> pos;
  square({0, 0}, t, pos, power);
  auto w = waypoints();
  w.insert(w.begin() + 1, Eigen::Vector3d(300, 300, 10));
  const FlightTimes ft = flightTimes(t, pos, power, w);
  EXPECT_TRUE(std::isnan(ft.passage_s[1]));
  EXPECT_TRUE(std::isnan(ft.leg_s[0]));
  EXPECT_TRUE(std::isnan(ft.leg_s[1]));
  EXPECT_NEAR(ft.leg_s[2], 20.0, 0.11);  // the matched neighbours still give their leg
}

// A stop at a waypoint is timed at the middle of the dwell, whatever the sampling: a 1 Hz log's
// closest sample can be anywhere in a 3 s stop (the old estimator's +-1.5 s per passage made the
// leg times of a flight with holds up to 30 % noisy), the dwell's entry and exit are interpolated.
TEST(MissionCalibration, AStopIsTimedAtTheMiddleOfItsDwellWhateverTheSamplingPhase) {
  // East at 5 m/s to (100, 0), stopped from t = 20 s to 23 s within 0.3 m of it, north at 5 m/s
  // through (100, 100) at 43 s.
  auto at = [](double time) -> Eigen::Vector3d {
    if (time <= 20.0) return {5.0 * time, 0.0, 10.0};
    if (time <= 23.0) return {100.0 + 0.3 * std::sin(4.0 * time), 0.3 * std::cos(3.0 * time) - 0.3, 10.0};
    return {100.0, 5.0 * (time - 23.0), 10.0};
  };
  const std::vector<Eigen::Vector3d> w = {{100, 0, 10}, {100, 100, 10}};
  for (double phase : {0.0, 0.25, 0.5, 0.75}) {
    std::vector<double> t, power;
    std::vector<Eigen::Vector3d> pos;
    for (double time = phase; time <= 50.0; time += 1.0) {
      t.push_back(time);
      pos.push_back(at(time));
      power.push_back(200.0);
    }
    const FlightTimes ft = flightTimes(t, pos, power, w);
    ASSERT_EQ(ft.passage_s.size(), 2u);
    // Into a sphere of 2 m beyond the closest approach at 19.6 s, out of it at 23.4 s.
    EXPECT_NEAR(ft.passage_s[0] + t.front(), 21.5, 0.15) << "sampling phase " << phase;
    // The next waypoint is flown through at 43 s: its passage is the closest approach.
    EXPECT_NEAR(ft.passage_s[1] + t.front(), 43.0, 0.05) << "sampling phase " << phase;
    ASSERT_EQ(ft.leg_energy_j.size(), 1u);
    EXPECT_NEAR(ft.leg_energy_j[0], 200.0 * ft.leg_s[0], 1e-6);  // energy between the interpolated passages
  }
}

namespace {

// A 100 m square of fast waypoints at 6 m/s, 10 m up, near Pisa, then RTL.
const char* kSquare =
    "QGC WPL 110\n"
    "0\t1\t0\t16\t0\t0\t0\t0\t43.7159500\t10.4613000\t0\t1\n"
    "1\t0\t3\t22\t0\t0\t0\t0\t43.7159500\t10.4613000\t10\t1\n"
    "2\t0\t2\t178\t1\t6\t-1\t0\t0\t0\t0\t1\n"
    "3\t0\t3\t16\t0\t0\t0\t0\t43.7168500\t10.4613000\t10\t1\n"
    "4\t0\t3\t16\t0\t0\t0\t0\t43.7168500\t10.4625430\t10\t1\n"
    "5\t0\t3\t16\t0\t0\t0\t0\t43.7159500\t10.4625430\t10\t1\n"
    "6\t0\t3\t16\t0\t0\t0\t0\t43.7159500\t10.4613000\t10\t1\n"
    "7\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";

// The square flown by the ArduCopter 3.x model with WPNAV_ACCEL `accel` [cm/s/s], as a log of
// constant 200 W from the take-off command to the end: what a vehicle set up that way would log.
// `launch` [m]: where the vehicle armed and took off, east and north of the file's home row; the
// log's positions are metres from there, as an autopilot logs them.
MissionFlight flownSquare(const std::string& name, double accel, const wattswath::energy::Vehicle& v,
                          const Eigen::Vector2d& launch = Eigen::Vector2d::Zero()) {
  namespace ms = wattswath::mission;
  MissionFlight f;
  f.name = name;
  f.mission = ms::parseQgcWpl(kSquare, name);
  ms::AutopilotConfig ap = ms::parseAutopilot(v.autopilot_json, v.name);  // ArduCopter 3.x, the leash model
  ap.parameters["WPNAV_ACCEL"] = accel;
  ms::FlightSettings fs;
  fs.dt = 0.02;
  fs.airframe = ms::airframeOfVehicle(v, v.name);
  const ms::Mission armed = missionLaunchedAt(f.mission, launch);  // the autopilot's home is where it armed
  const auto flown = ms::flyMission(ms::sequenceMission(armed), ap, fs);
  for (const auto& s : flown.samples) {
    wattswath::logs::LogSample l;
    l.t = s.t;
    l.position = s.position;
    l.velocity = s.velocity;
    l.voltage = 12.0;
    l.current = 200.0 / 12.0;
    l.power = 200.0;
    f.log.samples.push_back(l);
  }
  f.log.source = name;
  return f;
}

// The IRIS+ vehicle (ArduCopter 3.2, the leash model), a hover-only energy model and its autopilot.
struct IrisPlus {
  wattswath::energy::Vehicle v = wattswath::energy::loadVehicle(
      wattswath::test::sourcePath("data/vehicles/iris-plus-arducopter3.json"));
  wattswath::energy::EnergyModel model = wattswath::energy::buildModel(v, {"hover"});
  wattswath::mission::AutopilotConfig ap = wattswath::mission::parseAutopilot(v.autopilot_json, v.name);
};

// Calibration settings fitting the flight behaviour only, with `evaluations` simulated flights per fit.
CalibrationSettings behaviourOnly(int evaluations) {
  CalibrationSettings cs;
  cs.max_evaluations = evaluations;
  cs.fit_energy = false;
  return cs;
}

}  // namespace

TEST(MissionCalibration, FlightsSetUpWithDifferentAccelerationsAreToldApartAndSaidToDisagree) {
  // Two logs of one mission flown with WPNAV_ACCEL 60 and 200 cm/s/s: each flight alone wants its
  // own value, and the calibration says the flights do not agree instead of only printing the
  // compromise. Two flights flown alike agree.
  const IrisPlus ip;
  const auto& [v, model, ap] = ip;
  CalibrationSettings cs = behaviourOnly(40);
  const auto apart = calibrateMissions({flownSquare("slow.csv", 60, v), flownSquare("quick.csv", 200, v)}, v, model, ap, cs);
  ASSERT_EQ(apart.per_flight.size(), 2u);
  EXPECT_EQ(apart.acceleration_parameter, "WPNAV_ACCEL");
  EXPECT_NEAR(apart.per_flight[0].value, 60.0, 12.0);
  // The quick flight cuts its corners: the track alignment (built for GPS offsets) moves it by
  // 0.4 m and its passages with it, so its own value comes out near 140, still far from the slow one.
  EXPECT_GT(apart.per_flight[1].value, 1.8 * apart.per_flight[0].value);
  EXPECT_FALSE(apart.flights_agree);
  bool said = false;
  for (const auto& n : apart.notes) said = said || n.find("the flights do not agree on WPNAV_ACCEL") != std::string::npos;
  EXPECT_TRUE(said);
  // Each flight's mission kind is kept with its value, and stored and read back with its name.
  EXPECT_EQ(apart.per_flight[0].kind.fast_waypoints, apart.coverage.fast_waypoints / 2);
  EXPECT_GT(apart.per_flight[0].kind.fast_waypoints, 0);
  const auto stored = nlohmann::json::parse(calibrationToJson(apart));
  ASSERT_EQ(stored["per_flight"]["kinds"].size(), 2u);
  EXPECT_EQ(stored["per_flight"]["flights"][1], "quick.csv");
  EXPECT_EQ(stored["per_flight"]["kinds"][0]["fast_waypoints"], apart.per_flight[0].kind.fast_waypoints);
  const auto alike = calibrateMissions({flownSquare("a.csv", 100, v), flownSquare("b.csv", 100, v)}, v, model, ap, cs);
  EXPECT_TRUE(alike.flights_agree);
  ASSERT_EQ(alike.per_flight.size(), 2u);
  EXPECT_NEAR(alike.per_flight[0].value, alike.per_flight[1].value, 0.1 * alike.per_flight[1].value);
}

TEST(MissionCalibration, BehaviourParametersTheFlightsDoNotCallToChangeKeepTheirStart) {
  // A log of the square flown with WPNAV_ACCEL 60 cm/s/s and every other parameter at its default.
  // Its corners and speed-ups call for the lower acceleration, so WPNAV_ACCEL is fitted (near 60);
  // a parameter whose return to its starting value (the others re-fitted) costs at most 1 % of the
  // time misfit keeps that value and is said to. With keep_share and keep_significance 0 every
  // fitted value is kept.
  const IrisPlus ip;
  const auto& [v, model, ap] = ip;
  CalibrationSettings cs = behaviourOnly(60);
  const MissionFlight slow = flownSquare("slow.csv", 60, v);
  const auto r = calibrateMissions({slow}, v, model, ap, cs);
  auto kept = [](const CalibrationResult& c, const std::string& n) {
    return std::find(c.kept_at_start.begin(), c.kept_at_start.end(), n) != c.kept_at_start.end();
  };
  EXPECT_FALSE(kept(r, "WPNAV_ACCEL"));
  EXPECT_NEAR(r.autopilot.get("WPNAV_ACCEL"), 60.0, 12.0);
  ASSERT_FALSE(r.kept_at_start.empty());
  for (const auto& n : r.kept_at_start) {
    EXPECT_EQ(r.autopilot.get(n), ap.get(n)) << n;  // exactly its starting value
    bool said = false;
    for (const auto& note : r.notes) said = said || note.rfind(n + " kept at its starting value", 0) == 0;
    EXPECT_TRUE(said) << n;
  }
  const auto stored = nlohmann::json::parse(calibrationToJson(r));
  EXPECT_EQ(stored["kept_at_start"].size(), r.kept_at_start.size());
  cs.keep_share = 0.0;
  cs.keep_significance = 0.0;
  EXPECT_TRUE(calibrateMissions({slow}, v, model, ap, cs).kept_at_start.empty());
  cs.keep_share = 1.5;
  EXPECT_THROW(calibrateMissions({slow}, v, model, ap, cs), std::invalid_argument);
  cs.keep_share = 0.01;
  cs.keep_significance = 0.6;
  EXPECT_THROW(calibrateMissions({slow}, v, model, ap, cs), std::invalid_argument);
}

TEST(MissionCalibration, TheFlightIsPredictedFromWhereTheLogTookOffNotFromTheFilesHome) {
  // The vehicle armed 25 m from the file's home row (20 m E, 15 m S), as the shared IRIS+ flights
  // did (3-27 m). The autopilot's home is the arming point: it climbs and returns there. The
  // comparison finds that point from the track and flies the mission from it, so a perfect model
  // predicts the log's time; flown from the file's home the return leg is 25 m shorter.
  const auto v = wattswath::energy::loadVehicle(wattswath::test::sourcePath("data/vehicles/iris-plus-arducopter3.json"));
  const auto model = wattswath::energy::buildModel(v, {"hover"});
  const auto ap = wattswath::mission::parseAutopilot(v.autopilot_json, v.name);
  const MissionFlight f = flownSquare("away.csv", 100, v, {20.0, -15.0});
  const FlightComparison c = compareFlight(f, v, model, ap);
  EXPECT_NEAR(c.launch.x(), 20.0, 0.6);
  EXPECT_NEAR(c.launch.y(), -15.0, 0.6);
  EXPECT_LT(std::abs(c.time_error_pct), 0.5);
  EXPECT_LT(std::abs(c.predicted.return_s - c.measured.return_s), 1.0);
  const auto from_file = wattswath::mission::predictMission(f.mission, v, model, ap);
  EXPECT_GT(std::abs(from_file.total.time_s - c.measured.total_s), 3.0);  // what the comparison used to predict
}

TEST(MissionCalibration, ALogWithAGeodeticOriginPlacesTheMissionsHomeThroughIt) {
  // An autopilot log measures its positions from its EKF origin, which it records (ORGN,
  // vehicle_local_position.ref_lat/lon): the mission's home row is placed in the log's frame through
  // it, exactly, not by laying the track onto the waypoints. Here the origin is 30 m west and 10 m
  // north of the file's home, and the vehicle armed 20 m east and 15 m south of it: the log reads
  // 50 m east and 25 m south of its origin at take-off, the offset is (30, -10) to the centimetre
  // and the launch point (20, -15).
  namespace geo = wattswath::geometry;
  const auto v = wattswath::energy::loadVehicle(wattswath::test::sourcePath("data/vehicles/iris-plus-arducopter3.json"));
  MissionFlight f = flownSquare("geodetic.bin", 100, v, {20.0, -15.0});
  const geo::LocalFrame home(f.mission.home);
  const geo::GeoPoint origin = home.toGeodetic(geo::Point(-30.0, 10.0));
  const Eigen::Vector2d home_in_log = geo::LocalFrame(origin).toLocal(f.mission.home.lat_deg, f.mission.home.lon_deg);
  // flownSquare's samples are measured from where it armed; as measured from the origin:
  for (auto& s : f.log.samples) s.position.head<2>() += home_in_log + Eigen::Vector2d(20.0, -15.0);
  f.log.has_geodetic_origin = true;
  f.log.origin_lat_deg = origin.lat_deg;
  f.log.origin_lon_deg = origin.lon_deg;
  f.log.origin_alt_m = origin.alt_m;
  Eigen::Vector2d offset, launch;
  missionFromLaunch(f, &offset, &launch);
  EXPECT_NEAR(offset.x(), 30.0, 0.01);
  EXPECT_NEAR(offset.y(), -10.0, 0.01);
  EXPECT_NEAR(launch.x(), 20.0, 0.01);
  EXPECT_NEAR(launch.y(), -15.0, 0.01);
}

TEST(MissionCalibration, TrackingErrorIsTheMedianCruiseDistanceFromTheLegsCornersAndHoversLeftOut) {
  // A square flown at 5 m/s, swinging 0.8 m either side of its line and 0.3 m above and below it;
  // within 10 m of a corner it is 3 m off (the model flies corners itself), and a stretch flown
  // at 1 m/s is 4 m off (hovering is not cruise). The medians are the swing.
  std::vector<double> t;
  std::vector<Eigen::Vector3d> pos, vel;
  const std::vector<Eigen::Vector3d> wps = {{0, 0, 10}, {100, 0, 10}, {100, 100, 10}, {0, 100, 10}, {0, 0, 10}};
  int k = 0;
  for (std::size_t c = 1; c < wps.size(); ++c) {
    const Eigen::Vector3d u = (wps[c] - wps[c - 1]) / 100.0, n(-u.y(), u.x(), 0.0);
    for (double s = 0.0; s < 100.0; s += 0.5, ++k) {
      const bool corner = s < 10.0 || s > 90.0, slow = c == 3 && s > 40.0 && s < 60.0;
      const double side = (k % 2 ? 1.0 : -1.0) * (corner ? 3.0 : slow ? 4.0 : 0.8);
      pos.push_back(wps[c - 1] + u * s + n * side + Eigen::Vector3d(0, 0, k % 3 ? 0.3 : -0.3));
      vel.push_back(u * (slow ? 1.0 : 5.0));
      t.push_back(0.1 * k);
    }
  }
  const TrackingMeasurement m = measureTrackingError(t, pos, vel, wps, 0.0, 1e9);
  ASSERT_TRUE(m.measured);
  EXPECT_NEAR(m.error.horizontal_m, 0.8, 1e-9);
  EXPECT_NEAR(m.error.vertical_m, 0.3, 1e-9);
  EXPECT_EQ(m.samples, 4 * 161 - 39);  // 10 to 90 m along each side, less the slow stretch
  // Outside the passages' time window nothing is cruise; too few samples measure nothing.
  const TrackingMeasurement none = measureTrackingError(t, pos, vel, wps, 0.0, 1.5);
  EXPECT_FALSE(none.measured);
  EXPECT_EQ(none.error.horizontal_m, 0.0);
}

TEST(MissionCalibration, TheStoredTrackingErrorIsReadBackAndAMalformedOneNamesItsField) {
  auto v = wattswath::energy::loadVehicle(wattswath::test::sourcePath("data/vehicles/iris-plus-arducopter3.json"));
  v.extensions["calibration"] = R"({"effects":["hover"],"tracking_error_m":{"horizontal":0.6,"vertical":0.15,"samples":200}})";
  const auto cm = calibratedModel(v);
  ASSERT_TRUE(cm.has_value());
  EXPECT_DOUBLE_EQ(cm->tracking_error.horizontal_m, 0.6);
  EXPECT_DOUBLE_EQ(cm->tracking_error.vertical_m, 0.15);
  v.extensions["calibration"] = R"({"effects":["hover"],"tracking_error_m":{"horizontal":-1,"vertical":0.15}})";
  try {
    calibratedModel(v);
    FAIL() << "a negative tracking error was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("tracking_error_m.horizontal = -1"), std::string::npos) << e.what();
  }
  v.extensions["calibration"] = R"({"effects":["hover"]})";
  EXPECT_EQ(calibratedModel(v)->tracking_error.horizontal_m, 0.0);  // older files: on the line
}

TEST(CalibrationCoverage, WaypointKindsAndSpeedsAreCountedAndTheOutsideIsSaidWhy) {
  using wattswath::mission::NavStep;
  const auto ap = wattswath::mission::parseAutopilot(R"({"firmware":"ArduCopter","version":"3.2"})", "test");
  auto step = [](NavStep::Kind k, Eigen::Vector3d at, double hold, double speed) {
    NavStep s;
    s.kind = k;
    s.target = at;
    s.hold_s = hold;
    s.speed_xy = speed;
    return s;
  };
  // Take-off, two fast legs (the second at the default WPNAV_SPEED, 5 m/s), a 2 s stop at 8 m/s,
  // a climb on the spot (no horizontal leg), RTL.
  const std::vector<NavStep> steps = {step(NavStep::Kind::Takeoff, {0, 0, 10}, 0, 0),
                                      step(NavStep::Kind::Waypoint, {100, 0, 10}, 0, 4),
                                      step(NavStep::Kind::Waypoint, {100, 100, 10}, 0, 0),
                                      step(NavStep::Kind::Waypoint, {0, 100, 10}, 2, 8),
                                      step(NavStep::Kind::Waypoint, {0, 100, 30}, 0, 12),
                                      step(NavStep::Kind::ReturnToLaunch, {0, 0, 0}, 0, 0)};
  const MissionKind k = missionKind(steps, ap);
  EXPECT_EQ(k.fast_waypoints, 3);
  EXPECT_EQ(k.stop_waypoints, 1);
  EXPECT_DOUBLE_EQ(k.speed_lo_mps, 4.0);
  EXPECT_DOUBLE_EQ(k.speed_hi_mps, 8.0);  // the 12 m/s climb has no horizontal leg
  EXPECT_TRUE(outsideCalibration(k, k).empty());
  const MissionKind fast_only{0, 30, 3.8, 7.5};
  const auto why = outsideCalibration(k, fast_only);
  ASSERT_EQ(why.size(), 1u);  // 8 m/s is within 10 % of 7.5
  EXPECT_NE(why[0].find("stops at 1 waypoint(s)"), std::string::npos) << why[0];
  const MissionKind both = combine(fast_only, MissionKind{5, 0, 2.0, 6.0});
  EXPECT_EQ(both.stop_waypoints, 5);
  EXPECT_DOUBLE_EQ(both.speed_lo_mps, 2.0);
  EXPECT_DOUBLE_EQ(both.speed_hi_mps, 7.5);
  EXPECT_TRUE(outsideCalibration(k, both).empty());
  // A circle (NAV_LOITER_TURNS) the calibration never flew is named; a file that does not record circles is not compared.
  MissionKind circling = k, no_circles = k, unrecorded = k;
  circling.circles = 2;
  no_circles.circles = 0;
  unrecorded.circles = -1;
  ASSERT_EQ(outsideCalibration(circling, no_circles).size(), 1u);
  EXPECT_NE(outsideCalibration(circling, no_circles)[0].find("circles 2 time(s)"), std::string::npos);
  EXPECT_TRUE(outsideCalibration(circling, unrecorded).empty());
  EXPECT_EQ(k.circles, 0);
  const auto slow = outsideCalibration(k, MissionKind{5, 30, 5.0, 6.0});  // 4 m/s is below 5 / 1.1
  ASSERT_EQ(slow.size(), 1u);
  EXPECT_NE(slow[0].find("commands 4 to 8 m/s; the calibration flights 5 to 6 m/s"), std::string::npos) << slow[0];
  // Legs, turns and climbs: three 100 m legs, median 100 m (the climb on the spot is none), 90 deg turns at the
  // two waypoints without a hold (the stop's turn is not flown through), 20 m up on a leg (the
  // take-off's climb is not a leg's).
  EXPECT_DOUBLE_EQ(k.leg_lo_m, 100.0);
  EXPECT_DOUBLE_EQ(k.leg_hi_m, 100.0);
  EXPECT_NEAR(k.turn_hi_deg, 90.0, 1e-9);
  EXPECT_DOUBLE_EQ(k.climb_hi_m, 20.0);
  MissionKind gentle = both;  // long legs, 45 deg turns, 2 m climbs
  gentle.leg_lo_m = 250.0;
  gentle.leg_hi_m = 400.0;
  gentle.turn_hi_deg = 45.0;
  gentle.climb_hi_m = 2.0;
  const auto sharp = outsideCalibration(k, gentle);
  ASSERT_EQ(sharp.size(), 3u);
  EXPECT_NE(sharp[0].find("median leg is 100 m; the calibration flights' 250 m or more"), std::string::npos) << sharp[0];
  EXPECT_NE(sharp[1].find("turns by up to 90 deg"), std::string::npos) << sharp[1];
  EXPECT_NE(sharp[2].find("change height by up to 20 m; the calibration flights' by up to 2.0 m"), std::string::npos) << sharp[2];
  gentle.leg_lo_m = 199.0;   // a median of 100 m is just over half of it
  gentle.turn_hi_deg = 70.0;  // 90 is within 20 deg of it
  gentle.climb_hi_m = 15.0;   // 20 is below 15 + 5
  EXPECT_TRUE(outsideCalibration(k, gentle).empty());
  const MissionKind joined = combine(gentle, k);
  EXPECT_DOUBLE_EQ(joined.leg_lo_m, 100.0);
  EXPECT_DOUBLE_EQ(joined.leg_hi_m, 400.0);
  EXPECT_DOUBLE_EQ(joined.turn_hi_deg, 90.0);
  EXPECT_DOUBLE_EQ(joined.climb_hi_m, 20.0);
}

TEST(MissionCalibration, TimeSpentSlowAndLegPeaksAreMeasuredOverOneSecondWindows) {
  // The square at 5 m/s (10 Hz) with a 2 s hover at its second corner (without it nothing is
  // slow: ConstantSpeedTrackGivesExactLegTimesAndEnergy): the forward 1 s windows are below 1 m/s
  // from 0.2 s before the hover to 0.2 s after its last second, 1.4 s; the legs still peak at 5 m/s.
  std::vector<double> t, power;
  std::vector<Eigen::Vector3d> pos;
  square({0, 0}, t, pos, power);
  std::size_t at = 0;
  while ((pos[at] - Eigen::Vector3d(100, 100, 10)).norm() > 1e-9) ++at;
  std::vector<double> th(t.begin(), t.begin() + static_cast<long>(at) + 1), ph(power.begin(), power.begin() + static_cast<long>(at) + 1);
  std::vector<Eigen::Vector3d> xh(pos.begin(), pos.begin() + static_cast<long>(at) + 1);
  for (int k = 1; k <= 20; ++k) th.push_back(t[at] + 0.1 * k), xh.push_back(pos[at]), ph.push_back(200.0);
  for (std::size_t i = at + 1; i < t.size(); ++i) th.push_back(t[i] + 2.0), xh.push_back(pos[i]), ph.push_back(200.0);
  const FlightTimes hover = flightTimes(th, xh, ph, waypoints());
  EXPECT_NEAR(hover.slow_s, 1.4, 0.11);
  for (double v : hover.leg_peak_mps) EXPECT_NEAR(v, 5.0, 1e-9);
}
