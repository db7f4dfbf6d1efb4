// predict's notes on what a .plan says it was written for (firmwareType, vehicleType) against the
// vehicle that flies it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "flight_test_util.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/predict.hpp"

using namespace wattswath::mission;
using wattswath::mission::testing::joined;
using wattswath::mission::testing::localMission;

namespace {

// `m` predicted for the IRIS vehicle (hover and kinetic effects) flown by `ap`.
MissionPrediction irisPrediction(const Mission& m, const AutopilotConfig& ap) {
  const wattswath::energy::Vehicle v =
      wattswath::energy::loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json");
  const wattswath::energy::EnergyModel model = wattswath::energy::buildModel(v, {"hover", "kinetic"});
  return predictMission(m, v, model, ap, PredictSettings{});
}

// The notes of `m` predicted for the IRIS vehicle flown by `ap`, joined one per line.
std::string notesOf(const Mission& m, const AutopilotConfig& ap) { return joined(irisPrediction(m, ap).warnings); }

AutopilotConfig px4() {
  AutopilotConfig a;
  a.family = AutopilotFamily::PX4;
  a.firmware = "PX4";
  a.version = "1.15";
  return a;
}

}  // namespace

TEST(PredictNotes, APlanWrittenForTheOtherFirmwareSaysSoAndWhichFirmwareFliesIt) {
  Mission m = localMission({{100, 0, 10}});
  m.source = "survey.plan";
  m.firmware_type = 3;  // ArduPilot
  m.vehicle_type = 2;
  EXPECT_EQ(notesOf(m, AutopilotConfig{}).find("was written for"), std::string::npos);
  const std::string on_px4 = notesOf(m, px4());
  EXPECT_NE(on_px4.find("survey.plan: the .plan was written for ArduPilot (firmwareType 3) and is predicted as the "
                        "vehicle's PX4 1.15 flies it"),
            std::string::npos)
      << on_px4;
  m.firmware_type = 12;  // PX4
  EXPECT_EQ(notesOf(m, px4()).find("was written for"), std::string::npos);
  EXPECT_NE(notesOf(m, AutopilotConfig{}).find("was written for PX4 (firmwareType 12) and is predicted as the vehicle's "
                                               "ArduCopter 4.5 flies it"),
            std::string::npos);
  m.firmware_type = 0;  // a WPL file or a generic .plan says nothing
  EXPECT_EQ(notesOf(m, px4()).find("was written for"), std::string::npos);
}

TEST(PredictNotes, APlanWrittenForAFixedWingOrVtolIsFlownAsTheMulticopterAndSaysSo) {
  Mission m = localMission({{100, 0, 10}});
  m.source = "plane.plan";
  m.firmware_type = 3;
  for (int rotary : {0, 2, 13, 14}) {
    m.vehicle_type = rotary;
    EXPECT_EQ(notesOf(m, AutopilotConfig{}).find("was written for"), std::string::npos) << rotary;
  }
  m.vehicle_type = 1;
  EXPECT_NE(notesOf(m, AutopilotConfig{}).find("plane.plan: the .plan was written for a fixed-wing aircraft (vehicleType "
                                               "1); it is predicted as the vehicle file's multicopter flies it"),
            std::string::npos);
  m.vehicle_type = 20;
  EXPECT_NE(notesOf(m, AutopilotConfig{}).find("a VTOL aircraft (vehicleType 20)"), std::string::npos);
}

namespace {

const std::string kWplHome = "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t43.7160040\t10.4613040\t7.15\t1\n";

MissionPrediction predictText(const std::string& text, const std::string& name, const AutopilotConfig& ap = {}) {
  return irisPrediction(parseQgcWpl(text, name), ap);
}

}  // namespace

// AP_Mission::is_takeoff_next skips NAV_DELAY when it checks that a mission starts with a take-off,
// and ModeAuto waits the delay out on the ground (ArduPilot's NavDelayTakeoffAbsTime test mission).
// The prediction leaves the wait out and says so; it flew 60 s of hover at an invented 10 m before.
TEST(PredictNotes, ANavDelayBeforeTheTakeOffIsWaitedOnTheGroundAndLeftOutOfTheFlight) {
  const std::string takeoff = "2\t0\t3\t22\t0\t0\t0\t0\t0\t0\t20\t1\n3\t0\t3\t16\t0\t0\t0\t0\t43.7170\t10.4613\t20\t1\n"
                              "4\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const MissionPrediction with = predictText(kWplHome + "1\t0\t2\t93\t60\t-1\t-1\t-1\t0\t0\t0\t1\n" + takeoff, "delay.waypoints");
  const MissionPrediction without = predictText(kWplHome + "1\t0\t2\t183\t9\t1500\t0\t0\t0\t0\t0\t1\n" + takeoff, "plain.waypoints");
  EXPECT_NEAR(with.total.time_s, without.total.time_s, 1e-9);
  EXPECT_NEAR(with.total.energy_j, without.total.energy_j, 1e-6);
  EXPECT_EQ(with.flight.steps.front().kind, NavStep::Kind::Takeoff);
  const std::string notes = joined(with.warnings);
  EXPECT_NE(notes.find("delay.waypoints:3: NAV_DELAY of 60 s before the take-off: ArduCopter waits it out on the ground"),
            std::string::npos) << notes;
  EXPECT_EQ(notes.find("no NAV_TAKEOFF first"), std::string::npos) << notes;
}

// ArduCopter refuses AUTO on the ground without a take-off ("Auto: Missing Takeoff Cmd"); the
// prediction climbs to the first item's altitude (it took 10 m for an item without a position,
// where ArduPilot's inf_loop test mission loiters at 100 m) and says both.
TEST(PredictNotes, AMissionWithoutATakeOffClimbsToTheFirstItemsAltitudeAndSaysArduCopterWouldNotStartIt) {
  const MissionPrediction p =
      predictText(kWplHome + "1\t0\t3\t19\t5\t0\t1\t0\t0\t0\t100\t1\n2\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n", "loiter.waypoints");
  ASSERT_EQ(p.flight.steps.front().kind, NavStep::Kind::Takeoff);
  EXPECT_DOUBLE_EQ(p.flight.steps.front().target.z(), 100.0);
  const std::string notes = joined(p.warnings);
  EXPECT_NE(notes.find("\"Auto: Missing Takeoff Cmd\""), std::string::npos) << notes;
  EXPECT_NE(notes.find("a vertical climb to 100 m (the first item's altitude)"), std::string::npos) << notes;
}

// ModeAuto::takeoff_start lifts the target to at least 1 m above the vehicle when it is landed
// (ArduPilot's TakeoffAlt test mission: "-10m is invalid, so it is set to 1m").
TEST(PredictNotes, ATakeOffBelowOneMetreClimbsOneMetreAndSaysSo) {
  const MissionPrediction p = predictText(kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t-10\t1\n", "low.waypoints");
  double top = -1e9;
  for (const FlightSample& s : p.flight.samples) top = std::max(top, s.position.z());
  EXPECT_NEAR(top, 1.0, 0.05);
  EXPECT_NE(joined(p.warnings).find("low.waypoints:3: NAV_TAKEOFF to -10 m above home: ArduCopter climbs at least 1 m"),
            std::string::npos);
}

// Items above terrain (MAV_FRAME 10) are flown as heights above home without terrain data: said,
// naming the first and the count, where it was said only in docs/missions.md.
TEST(PredictNotes, TerrainFrameItemsAreFlownOverFlatGroundAndSaid) {
  const std::string text = kWplHome + "1\t0\t10\t22\t0\t0\t0\t0\t0\t0\t15\t1\n2\t0\t10\t16\t0\t0\t0\t0\t43.7170\t10.4613\t15\t1\n"
                           "3\t0\t3\t16\t0\t0\t0\t0\t43.7170\t10.4623\t15\t1\n4\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const std::string notes = joined(predictText(text, "terrain.waypoints").warnings);
  EXPECT_NE(notes.find("terrain.waypoints:3: 2 item(s) give altitudes above terrain (MAV_FRAME 10/11); without terrain data"),
            std::string::npos) << notes;
}

// DO_CHANGE_SPEED above the vehicle file's max_speed_mps (16 m/s for the IRIS) is flown, as the
// autopilot takes it, and said with the fastest ground speed of the flight; DO_AUX_FUNCTION is
// assumed not to change the flight, and said. The model's parameter line is FlownMission::model,
// not a warning.
TEST(PredictNotes, ASpeedAboveTheVehiclesMaximumIsFlownAndSaid) {
  const std::string text = kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t20\t1\n2\t0\t2\t178\t1\t25\t-1\t0\t0\t0\t0\t1\n"
                           "3\t0\t2\t218\t70\t2\t0\t0\t0\t0\t0\t1\n4\t0\t3\t16\t0\t0\t0\t0\t43.7260\t10.4613\t20\t1\n"
                           "5\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const MissionPrediction p = predictText(text, "fast.waypoints");
  const std::string notes = joined(p.warnings);
  EXPECT_NE(notes.find("fast.waypoints:4: DO_CHANGE_SPEED asks for up to 25 m/s (1 item(s)), above the vehicle file's "
                       "max_speed_mps 16 m/s"),
            std::string::npos) << notes;
  double fastest = 0.0;
  for (const FlightSample& s : p.flight.samples) fastest = std::max(fastest, std::hypot(s.velocity.x(), s.velocity.y()));
  EXPECT_GT(fastest, 16.5);
  EXPECT_NE(notes.find("fast.waypoints:5: DO_AUX_FUNCTION 70 runs an auxiliary switch function"), std::string::npos) << notes;
  EXPECT_EQ(notes.find("S-curve model:"), std::string::npos) << notes;
  EXPECT_NE(p.flight.model.find("ArduCopter 4.5 S-curve model: WPNAV_SPEED 10 m/s"), std::string::npos) << p.flight.model;
}

// PX4's FeasibilityChecker::checkMissionItemValidity rejects a mission holding a command outside
// its list (DO_SET_SERVO, CONDITION_YAW, ...): a PX4 vehicle's prediction says so, naming the first
// such item; an ArduCopter vehicle's does not.
TEST(PredictNotes, APx4VehicleIsToldWhichItemsPx4sFeasibilityCheckRejects) {
  Mission m = localMission({{100, 0, 10}, {200, 0, 10}});
  MissionItem servo = m.items[1];
  servo.command = 183;  // DO_SET_SERVO
  servo.frame = 2;
  servo.lat_deg = servo.lon_deg = 0.0;
  servo.where = "servo.plan: mission.items[2]";
  m.items.insert(m.items.begin() + 2, servo);
  EXPECT_NE(notesOf(m, px4()).find("servo.plan: mission.items[2] (DO_SET_SERVO): 1 item(s) with commands PX4's mission "
                                   "feasibility check does not list"),
            std::string::npos)
      << notesOf(m, px4());
  EXPECT_EQ(notesOf(m, AutopilotConfig{}).find("feasibility check"), std::string::npos);
  EXPECT_EQ(notesOf(localMission({{100, 0, 10}}), px4()).find("feasibility check"), std::string::npos);
}

// PX4's FeasibilityChecker also rejects a take-off at or below home, a take-off after an item with
// a position, and a mission starting with a landing: noted for a PX4 vehicle only.
TEST(PredictNotes, APx4VehicleIsToldOfPx4sTakeOffRules) {
  Mission m = localMission({{100, 0, 10}, {200, 0, 10}});
  m.items[0].alt_m = 0.0;  // take-off to 0 m above home
  MissionItem again = m.items[0];
  again.alt_m = 20.0;
  again.where = "test item again";
  m.items.insert(m.items.begin() + 2, again);  // a second take-off after WP1
  const std::string notes = notesOf(m, px4());
  EXPECT_NE(notes.find("test item 1: NAV_TAKEOFF at or below home's altitude (0 m): PX4 rejects such a mission"),
            std::string::npos) << notes;
  EXPECT_NE(notes.find("test item again: NAV_TAKEOFF after an item with a position: PX4 rejects"), std::string::npos) << notes;
  EXPECT_EQ(notesOf(m, AutopilotConfig{}).find("PX4 rejects"), std::string::npos);
  EXPECT_EQ(notesOf(localMission({{100, 0, 10}}), px4()).find("PX4 rejects"), std::string::npos);
}

// NAV_LOITER_UNLIM (ArduPilot's AVC2013 and other test missions end their route with one) was
// refused as unsupported: the vehicle flies to it, stops and loiters until the pilot ends it. The
// prediction now ends on arrival, in the air, says so, and ignores the items after it.
TEST(PredictNotes, ALoiterWithoutLimitEndsThePredictionOnArrival) {
  const std::string text = kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t20\t1\n2\t0\t3\t17\t0\t0\t0\t0\t43.7170\t10.4613\t20\t1\n"
                           "3\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const MissionPrediction p = predictText(text, "loiter.waypoints");
  ASSERT_EQ(p.flight.steps.size(), 2u);  // take-off, the loiter point; the RTL is never flown
  const FlightSample& end = p.flight.samples.back();
  EXPECT_NEAR(end.position.y(), 111.0, 2.0);  // 0.001 deg of latitude north of home
  EXPECT_NEAR(end.position.z(), 20.0, 0.5);
  EXPECT_LT(end.velocity.norm(), 0.5);
  const std::string notes = joined(p.warnings);
  EXPECT_NE(notes.find("loiter.waypoints:4: NAV_LOITER_UNLIM: the autopilot loiters there until the pilot"), std::string::npos) << notes;
  EXPECT_NE(notes.find("loiter.waypoints:5: items after NAV_LOITER_UNLIM are never flown (1 ignored)"), std::string::npos) << notes;
  EXPECT_EQ(notes.find("does not end with NAV_RETURN_TO_LAUNCH"), std::string::npos) << notes;
}

// The battery model (Hwang et al.) reads its residual at the present current (Peukert), so it fell
// 7 points as the motors started and rose back at touch-down, and the verdict took the risen value
// (61 % where the curve had ended its flight at 54 % on the IRIS+ mission of 2017-10-18). The charge
// left is now counted as the autopilot counts it (drawn against the usable capacity): it starts at
// 100 %, never rises, and ends where the verdict reads it. A mission that never lands says it ends
// in the air.
TEST(PredictNotes, TheChargeLeftIsCountedAsTheAutopilotCountsItAndAFlightEndingInTheAirSaysSo) {
  const std::string route = "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t20\t1\n2\t0\t3\t16\t0\t0\t0\t0\t43.7190\t10.4613\t20\t1\n";
  const MissionPrediction landed = predictText(kWplHome + route + "3\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n", "rtl.waypoints");
  ASSERT_TRUE(landed.battery.known);
  const auto& u = landed.battery.usable_left;
  ASSERT_GE(u.size(), 10u);
  EXPECT_FALSE(landed.battery.ends_in_air);
  EXPECT_DOUBLE_EQ(u.front(), 1.0);
  for (std::size_t i = 1; i < u.size(); ++i) EXPECT_LE(u[i], u[i - 1] + 1e-12) << "t = " << landed.battery.t_s[i];
  // The first second draws about 1/3600 of an hour of hover current: well under a point, not 7.
  EXPECT_GT(u[1], 0.99);
  EXPECT_DOUBLE_EQ(landed.battery.usable_left_end, u.back());
  // Counted: the energy drawn over the usable energy, within the voltage's sag (a few %).
  EXPECT_LT(u.back(), 1.0);
  EXPECT_NE(landed.battery.verdict.find("lands with"), std::string::npos) << landed.battery.verdict;

  const MissionPrediction hovering = predictText(kWplHome + route, "hover.waypoints");
  EXPECT_TRUE(hovering.battery.ends_in_air);
  EXPECT_NE(hovering.battery.verdict.find("ends the mission in the air (return and landing not counted) with"), std::string::npos)
      << hovering.battery.verdict;
}

// A NAV_LAND with a position is flown to at altitude, then descended (ModeAuto::do_land,
// PX4's land item). The approach counted as "landing": a mission ending in a land 2986 m away put a
// 5:33 cruise in the landing phase (ArduPilot's QGC test plan). It is now a mission leg in every
// model, and the landing phase is the descent.
TEST(PredictNotes, TheApproachOfALandWithAPositionIsMissionFlightAndTheLandingIsTheDescent) {
  const std::string text = kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t20\t1\n2\t0\t3\t21\t0\t0\t0\t0\t43.7190\t10.4613\t0\t1\n";
  AutopilotConfig leash;
  leash.family = AutopilotFamily::ArduCopterLeash;
  leash.firmware = "ArduCopter";
  leash.version = "3.2";
  for (const AutopilotConfig& ap : {AutopilotConfig{}, leash, px4()}) {
    const MissionPrediction p = predictText(text, "land.waypoints", ap);
    const Totals& landing = p.phases[static_cast<int>(FlightPhase::Landing)];
    const Totals& mission = p.phases[static_cast<int>(FlightPhase::Mission)];
    EXPECT_GT(mission.distance_m, 300.0) << toString(ap.family);  // the 333 m approach at 20 m
    // The 20 m descent, and for PX4 the last metres to the land point closed while descending.
    EXPECT_LT(landing.distance_m, 30.0) << toString(ap.family);
  }
}

// PX4's MissionBase::on_active moves past a reached item only when its autocontinue is set: the
// prediction ends at the first item without it, in the air, and says so (it flew the whole mission,
// 2:42 where the vehicle stops after 0:30). ArduPilot does not keep the flag: noted, flown on.
TEST(PredictNotes, Px4StopsAtAnItemWithoutAutoContinueAndArduPilotFliesOn) {
  Mission m = localMission({{100, 0, 10}, {200, 0, 10}, {300, 0, 10}});
  m.items[2].autocontinue = false;  // the second waypoint
  m.items[2].where = "stop.plan: mission.items[2]";
  const MissionPrediction all = irisPrediction(localMission({{100, 0, 10}, {200, 0, 10}, {300, 0, 10}}), px4());
  const MissionPrediction stop = irisPrediction(m, px4());
  EXPECT_LT(stop.total.time_s, 0.7 * all.total.time_s);
  const FlightSample& end = stop.flight.samples.back();
  EXPECT_NEAR(end.position.x(), 200.0, 11.0);  // within NAV_ACC_RAD of the second waypoint
  EXPECT_NEAR(end.position.z(), 10.0, 1.0);
  const std::string notes = joined(stop.warnings);
  EXPECT_NE(notes.find("stop.plan: mission.items[2]: autoContinue is false: PX4 stops at this item and waits for the pilot"),
            std::string::npos) << notes;
  EXPECT_NE(notes.find("the 2 item(s) after it are not flown"), std::string::npos) << notes;
  const MissionPrediction ardu = irisPrediction(m, AutopilotConfig{});
  const MissionPrediction ardu_all = irisPrediction(localMission({{100, 0, 10}, {200, 0, 10}, {300, 0, 10}}), AutopilotConfig{});
  EXPECT_NEAR(ardu.total.time_s, ardu_all.total.time_s, 1e-9);
  EXPECT_NE(joined(ardu.warnings).find("autoContinue is false; ArduPilot does not keep it"), std::string::npos);
}

// PX4 keeps at most 500 mission items on NuttX hardware (navigation.h NUM_MISSIONS_SUPPORTED) and
// refuses a longer upload: a longer mission is flown and said not to fit a PX4 vehicle.
TEST(PredictNotes, AMissionLongerThanPx4KeepsIsSaid) {
  std::vector<Eigen::Vector3d> wps;
  for (int k = 0; k < 499; ++k) wps.emplace_back(10.0 * (k % 20), 10.0 * (k / 20), 10.0);
  const Mission m = localMission(wps);  // take-off, 499 waypoints, RTL: 501 items
  ASSERT_EQ(m.items.size(), 501u);
  EXPECT_NE(notesOf(m, px4()).find("test: 501 items: PX4 on flight-controller hardware keeps at most 500"), std::string::npos);
  EXPECT_EQ(notesOf(m, AutopilotConfig{}).find("items: PX4"), std::string::npos);
  wps.pop_back();
  EXPECT_EQ(notesOf(localMission(wps), px4()).find("items: PX4"), std::string::npos);
}

// The verdict's first words follow fits / fits_with_margin: a landing below the reserve began
// "Fits, but lands with 24.6 % ..." while the JSON said fits: false (the reviewer's jr2.waypoints
// on the 1.3 Ah IRIS). It now says it does not fit, and gives the charge with the margin too.
TEST(PredictNotes, AVerdictBelowTheReserveSaysItDoesNotFitAndGivesTheMarginFigure) {
  const wattswath::energy::Vehicle v =
      wattswath::energy::loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/tests/data/iris-small-battery.json");
  const wattswath::energy::EnergyModel model = wattswath::energy::buildModel(v, {"hover", "kinetic"});
  const Mission m = parseQgcWpl(kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t10\t1\n2\t0\t3\t16\t0\t0\t0\t0\t43.716904\t10.461304\t10\t1\n"
                                           "3\t0\t3\t16\t0\t0\t0\t0\t43.716904\t10.462547\t10\t1\n4\t0\t3\t20\t0\t0\t0\t0\t0\t0\t0\t1\n",
                                "jr.waypoints");
  PredictSettings s;
  const double left = predictMission(m, v, model, AutopilotConfig{}, s).battery.usable_left_end;
  s.reserve_fraction = std::min(0.9, left + 0.05);  // 5 points more than it lands with
  const BatteryPrediction b = predictMission(m, v, model, AutopilotConfig{}, s).battery;
  ASSERT_FALSE(b.fits);
  ASSERT_FALSE(b.depleted);
  EXPECT_EQ(b.verdict.rfind("Does not fit the reserve: lands with ", 0), 0u) << b.verdict;
  EXPECT_NE(b.verdict.find("; with 10 % more energy (the prediction's error margin, --energy-margin) "), std::string::npos)
      << b.verdict;
  EXPECT_EQ(b.verdict.find("Fits"), std::string::npos) << b.verdict;
  s.energy_margin = 0.0;
  const BatteryPrediction none = predictMission(m, v, model, AutopilotConfig{}, s).battery;
  EXPECT_EQ(none.verdict.rfind("Does not fit the reserve: ", 0), 0u) << none.verdict;
  EXPECT_EQ(none.verdict.find("more energy"), std::string::npos) << none.verdict;
}

// A waypoint below home's height was flown underground without a word (the reviewer's
// below.waypoints: samples at z = -30 m, "Fits"), and one 530 m up (frame 0 with home at 0 m) got
// no note. Below home is an error naming the item and its height (PX4's FeasibilityChecker::
// checkIfBelowHomeAltitude warns "Waypoint N below home"), a note with --lenient; more than 120 m
// above home is noted.
TEST(PredictNotes, AWaypointBelowHomeIsAnErrorOrWithLenientANoteAndOneHighUpIsNoted) {
  const std::string route = "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t10\t1\n2\t0\t3\t16\t0\t0\t0\t0\t43.716904\t10.461304\t-5\t1\n"
                            "3\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const Mission below = parseQgcWpl(kWplHome + route, "below.waypoints");
  for (const AutopilotConfig& ap : {AutopilotConfig{}, px4()}) {
    try {
      irisPrediction(below, ap);
      ADD_FAILURE() << "a waypoint below home was flown";
    } catch (const MissionError& e) {
      EXPECT_NE(std::string(e.what()).find("below.waypoints:4: NAV_WAYPOINT at -5 m above home (altitude -5 m in MAV_FRAME 3), "
                                           "expected at or above home's height"),
                std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("--lenient"), std::string::npos) << e.what();
    }
  }
  const wattswath::energy::Vehicle v =
      wattswath::energy::loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json");
  PredictSettings lenient;
  lenient.lenient = true;
  const MissionPrediction p = predictMission(below, v, wattswath::energy::buildModel(v, {"hover", "kinetic"}), {}, lenient);
  EXPECT_NE(joined(p.warnings).find("below.waypoints:4: NAV_WAYPOINT at -5 m above home"), std::string::npos) << joined(p.warnings);
  EXPECT_NE(joined(p.warnings).find("predicted as written (--lenient)"), std::string::npos);
  // Absolute (frame 0) altitudes count from home's: 40 m above sea level with home at 7.15 m is 32.85 m up.
  const std::string absolute = "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t10\t1\n2\t0\t0\t16\t0\t0\t0\t0\t43.716904\t10.461304\t5\t1\n"
                               "3\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  EXPECT_THROW(predictText(kWplHome + absolute, "amsl.waypoints"), MissionError);
  // 530 m above sea level with home at 7.15 m: noted, not refused.
  const std::string high = "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t10\t1\n2\t0\t0\t16\t0\t0\t0\t0\t43.716904\t10.461304\t530\t1\n"
                           "3\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const std::string notes = joined(predictText(kWplHome + high, "high.waypoints").warnings);
  EXPECT_NE(notes.find("high.waypoints:4: NAV_WAYPOINT at 522.85 m above home (altitude 530 m in MAV_FRAME 0, home at 7.15 m): "
                       "1 item(s) more than 120 m above home, up to 523 m"),
            std::string::npos) << notes;
  EXPECT_EQ(joined(predictText(kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t10\t1\n"
                               "2\t0\t3\t16\t0\t0\t0\t0\t43.716904\t10.461304\t119\t1\n3\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n",
                               "ok.waypoints").warnings).find("above home, up to"),
            std::string::npos);
}

// An altitude of 0 is the previous target's for ArduPilot (ModeAuto::loc_from_cmd, noted in the
// flight); PX4 takes it as written and flies down to home's height, which its FeasibilityChecker
// does not flag (not below home): noted for a PX4 vehicle, and flown so.
TEST(PredictNotes, AnAltitudeOfZeroIsFlownDownToHomeByPx4AndSaid) {
  const std::string text = kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t20\t1\n2\t0\t3\t16\t0\t0\t0\t0\t43.716904\t10.461304\t20\t1\n"
                           "3\t0\t3\t16\t0\t0\t0\t0\t43.716904\t10.462547\t0\t1\n4\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const MissionPrediction p = predictText(text, "alt0.waypoints", px4());
  EXPECT_NE(joined(p.warnings).find("alt0.waypoints:5: NAV_WAYPOINT at altitude 0 above home: PX4 flies to it as written, down "
                                    "to home's height"),
            std::string::npos) << joined(p.warnings);
  const MissionPrediction a = predictText(text, "alt0.waypoints");
  EXPECT_EQ(joined(a.warnings).find("PX4 flies to it as written"), std::string::npos);
  EXPECT_NE(joined(a.warnings).find("altitude 0 is the previous target's for ArduPilot (20 m)"), std::string::npos) << joined(a.warnings);
}

// PX4's upload (MavlinkMissionManager::parse_mavlink_mission_item) takes a position only in frames
// 0/3 (5/6 in an INT upload) and a command without one only in MAV_FRAME_MISSION (2); anything else
// is answered MAV_MISSION_UNSUPPORTED(_FRAME) and nothing is kept. A PX4 vehicle's prediction
// refuses such a mission naming the item and its frame (a note with --lenient); ArduCopter's flies it.
TEST(PredictNotes, APx4VehicleRefusesItemsInFramesPx4DoesNotTakeThem) {
  const std::string speed_in_3 = kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t10\t1\n2\t0\t3\t178\t1\t3\t-1\t0\t0\t0\t0\t1\n"
                                 "3\t0\t3\t16\t0\t0\t0\t0\t43.716904\t10.461304\t10\t1\n4\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const std::string terrain = kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t10\t1\n2\t0\t10\t16\t0\t0\t0\t0\t43.716904\t10.461304\t10\t1\n"
                              "3\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const auto refusal = [&](const std::string& text, const std::string& name) {
    try {
      predictText(text, name, px4());
    } catch (const MissionError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string speed = refusal(speed_in_3, "speed.waypoints");
  EXPECT_NE(speed.find("speed.waypoints:4: DO_CHANGE_SPEED in MAV_FRAME 3: PX4 refuses the upload (parse_mavlink_mission_item "
                       "answers MAV_MISSION_UNSUPPORTED): it takes a command without a position only in MAV_FRAME_MISSION (2)"),
            std::string::npos) << speed;
  EXPECT_NE(speed.find("--lenient"), std::string::npos) << speed;
  const std::string ground = refusal(terrain, "terrain.waypoints");
  EXPECT_NE(ground.find("terrain.waypoints:4: NAV_WAYPOINT in MAV_FRAME 10: PX4 refuses the upload"), std::string::npos) << ground;
  EXPECT_NE(ground.find("MAV_MISSION_UNSUPPORTED_FRAME"), std::string::npos) << ground;
  // ArduCopter takes both; the RTL in frame 3, as Mission Planner writes it, too.
  EXPECT_NO_THROW(predictText(speed_in_3, "speed.waypoints"));
  EXPECT_NO_THROW(predictText(terrain, "terrain.waypoints"));
  // --lenient: predicted as if accepted, with the note.
  const wattswath::energy::Vehicle v =
      wattswath::energy::loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json");
  PredictSettings lenient;
  lenient.lenient = true;
  const MissionPrediction p =
      predictMission(parseQgcWpl(speed_in_3, "speed.waypoints"), v, wattswath::energy::buildModel(v, {"hover", "kinetic"}), px4(), lenient);
  EXPECT_NE(joined(p.warnings).find("speed.waypoints:4: DO_CHANGE_SPEED in MAV_FRAME 3: PX4 refuses the upload"), std::string::npos);
  EXPECT_NE(joined(p.warnings).find("predicted as if accepted (--lenient)"), std::string::npos);
}

// PX4 turns the take-off item into a waypoint after the climb (Mission::set_mission_items: "navigate
// to the actual waypoint now"), so a take-off 100 m north of home is flown to; the model climbed in
// place and a prediction with it there equalled one with it at home. ArduCopter climbs where it is
// (ModeAuto::takeoff_start takes the altitude only), so its predictions stay equal.
TEST(PredictNotes, Px4FliesToTheTakeOffItemsPositionAfterTheClimbAndArduCopterDoesNot) {
  const auto text = [](const char* lat) {
    return kWplHome + "1\t0\t3\t22\t0\t0\t0\t0\t" + lat + "\t10.4613040\t10\t1\n2\t0\t3\t16\t0\t0\t0\t0\t43.716904\t10.462547\t10\t1\n"
           "3\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  };
  const std::string at_home = text("43.7160040"), north = text("43.716904");  // 100 m north
  const MissionPrediction px4_home = predictText(at_home, "home.waypoints", px4());
  const MissionPrediction px4_north = predictText(north, "north.waypoints", px4());
  EXPECT_GT(px4_north.total.distance_m - px4_home.total.distance_m, 30.0);
  // After the climb the vehicle reaches the take-off's position (within NAV_ACC_RAD) before item 2.
  const ItemPrediction& takeoff = px4_north.items[0];
  bool over = false;
  for (const FlightSample& s : px4_north.flight.samples)
    if (s.step == 0 && s.t <= takeoff.reached_s + 1e-9) over = over || s.position.y() > 85.0;
  EXPECT_TRUE(over);
  const MissionPrediction ac_home = predictText(at_home, "home.waypoints"), ac_north = predictText(north, "north.waypoints");
  EXPECT_NEAR(ac_north.total.energy_j, ac_home.total.energy_j, 1e-6);
  EXPECT_NEAR(ac_north.total.time_s, ac_home.total.time_s, 1e-9);
}

// Without a take-off item ArduCopter refuses to start on the ground, PX4 takes off vertically to
// the first item's altitude (Mission::do_need_vertical_takeoff): the note follows the autopilot (it
// said ArduCopter's rule for a PX4 vehicle). A first item that gives no altitude (a landing at 0 m)
// climbs to 10 m, said as a default (it said "the first item's altitude").
TEST(PredictNotes, TheAssumedTakeOffNoteFollowsTheAutopilotAndSaysWhenItsHeightIsADefault) {
  const std::string waypoint_first = kWplHome + "1\t0\t3\t16\t0\t0\t0\t0\t43.716904\t10.461304\t15\t1\n2\t0\t2\t20\t0\t0\t0\t0\t0\t0\t0\t1\n";
  const std::string on_px4 = joined(predictText(waypoint_first, "wp.waypoints", px4()).warnings);
  EXPECT_NE(on_px4.find("wp.waypoints: no NAV_TAKEOFF first: PX4 starts such a mission on the ground with a vertical take-off "
                        "to the first item's altitude"),
            std::string::npos) << on_px4;
  EXPECT_NE(on_px4.find("MIS_TKO_LAND_REQ"), std::string::npos);
  EXPECT_NE(on_px4.find("a vertical climb to 15 m (the first item's altitude)"), std::string::npos) << on_px4;
  EXPECT_EQ(on_px4.find("Missing Takeoff Cmd"), std::string::npos) << on_px4;
  const std::string on_ac = joined(predictText(waypoint_first, "wp.waypoints").warnings);
  EXPECT_NE(on_ac.find("\"Auto: Missing Takeoff Cmd\""), std::string::npos) << on_ac;
  const MissionPrediction land = predictText(kWplHome + "1\t0\t3\t21\t0\t0\t0\t0\t0\t0\t0\t1\n", "land_first.waypoints");
  EXPECT_DOUBLE_EQ(land.flight.steps.front().target.z(), 10.0);
  const std::string notes = joined(land.warnings);
  EXPECT_NE(notes.find("a vertical climb to 10 m (a default: the first item gives no altitude to climb to)"), std::string::npos)
      << notes;
  EXPECT_EQ(notes.find("(the first item's altitude)"), std::string::npos) << notes;
}
