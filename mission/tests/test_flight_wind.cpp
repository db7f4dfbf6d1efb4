// Wind in the flight-behaviour models, against hand-worked cases: the autopilot controls the ground
// velocity while the airframe's drag acts on the velocity through the air, so at the lean limit a
// headwind takes its own speed off the ground speed, a tailwind adds it, a crosswind takes the
// Pythagorean share; a hold keeps the vehicle on its waypoint; and predict takes the energy
// model's drag at air speed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flight_test_util.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/mission/predict.hpp"

using namespace wattswath::mission;
using wattswath::mission::testing::localMission;

namespace {

constexpr double kDrag = 0.0576;  // [1/m] c2 of the drag-limited airframe (test_flight.cpp, LeanLimitAndDragCapTheSpeed)
const double kLean = 9.80665 * std::tan(M_PI / 6.0);  // [m/s^2] 30 degrees of lean
const double kAirMax = std::sqrt(kLean / kDrag);       // [m/s] 9.91: the air speed at which drag takes all the lean

// [m/s] The highest horizontal ground speed of a 600 m leg east, WPNAV_SPEED 15 m/s, in `wind` [m/s].
double topGroundSpeed(const AutopilotConfig& base, const Eigen::Vector2d& wind) {
  AutopilotConfig ap = base;
  ap.parameters["WPNAV_SPEED"] = 1500;
  ap.parameters["ANGLE_MAX"] = 3000;
  FlightSettings fs;
  fs.airframe.drag_quadratic_per_m = kDrag;
  fs.airframe.wind = wind;
  const FlownMission f = flyMission(sequenceMission(localMission({{600, 0, 10}})), ap, fs);
  double v = 0.0;
  for (const auto& s : f.samples)
    if (s.phase == FlightPhase::Mission) v = std::max(v, s.velocity.head<2>().norm());
  return v;
}

AutopilotConfig arduCopter32() { return parseAutopilot(R"({"firmware":"ArduCopter","version":"3.2"})", "test"); }

}  // namespace

TEST(Wind, AtTheLeanLimitAHeadwindTakesItsSpeedOffTheGroundSpeedATailwindAddsIt) {
  // Drag c2 |v_air|^2 = g tan 30 deg at |v_air| = 9.91 m/s: calm 9.91, 4 m/s against 5.91, 4 m/s
  // behind 13.91 m/s over the ground (below WPNAV_SPEED 15). (Across the leg there is no such
  // figure: at the lean limit the controller lets the vehicle drift downwind, which the next test
  // keeps it from below the limit.)
  for (const AutopilotConfig& ap : {AutopilotConfig{}, arduCopter32()}) {
    SCOPED_TRACE(ap.firmware + " " + ap.version);
    EXPECT_NEAR(topGroundSpeed(ap, {0.0, 0.0}), kAirMax, 0.1);
    EXPECT_NEAR(topGroundSpeed(ap, {-4.0, 0.0}), kAirMax - 4.0, 0.1);
    EXPECT_NEAR(topGroundSpeed(ap, {4.0, 0.0}), kAirMax + 4.0, 0.15);
  }
}

TEST(Wind, BelowTheLeanLimitTheCruiseKeepsItsSpeedAndAHoldKeepsItsWaypoint) {
  // 5 m/s commanded, 6 m/s of wind from the north (towards the south) across a 300 m leg east with
  // a 10 s hold at its end: the velocity loop's integrator takes the drag, so the cruise is at the
  // command, the vehicle keeps within a metre of its line and sits on the waypoint at the end of
  // the hold.
  for (const AutopilotConfig& ap : {AutopilotConfig{}, arduCopter32()}) {
    SCOPED_TRACE(ap.firmware + " " + ap.version);
    FlightSettings fs;
    fs.airframe.drag_quadratic_per_m = 0.01;
    fs.airframe.wind = {0.0, -6.0};
    const FlownMission f = flyMission(sequenceMission(localMission({{300, 0, 10}}, 10.0, 5.0)), ap, fs);
    std::size_t k = 0;  // the waypoint's step
    while (k < f.steps.size() && f.steps[k].kind != NavStep::Kind::Waypoint) ++k;
    ASSERT_LT(k, f.steps.size());
    const StepEvent& e = f.events[k];
    double cruise = 0.0, off_line = 0.0;
    const FlightSample* end = nullptr;
    for (const auto& s : f.samples) {
      if (s.phase != FlightPhase::Mission) continue;
      if (std::abs(s.position.x() - 150.0) < 1.0) cruise = s.velocity.head<2>().norm();
      if (s.position.x() > 20.0 && s.position.x() < 280.0) off_line = std::max(off_line, std::abs(s.position.y()));
      if (s.t <= e.completed_s) end = &s;
    }
    EXPECT_NEAR(cruise, 5.0, 0.1);
    EXPECT_LT(off_line, 1.0);
    EXPECT_GT(off_line, 1e-3);  // the wind does push it (a straight leg in still air stays on the line)
    ASSERT_NE(end, nullptr);
    EXPECT_LT((end->position - Eigen::Vector3d(300, 0, 10)).norm(), 0.5);
  }
}

TEST(Wind, PredictTakesTheEnergyModelsDragAtAirSpeed) {
  // 400 m out and back at 5 m/s along a 4 m/s wind: the drag power 0.5 rho CdA |v - w|^3 / eta is
  // (9^3 + 1^3) / 2 = 365 against 5^3 = 125 in still air on the legs, so the flight costs more;
  // the breakdown's wind effect (which replaced parasitic_drag) equals that power summed over the
  // flown pieces.
  const wattswath::energy::Vehicle v = wattswath::energy::loadVehicle(std::string(WATTSWATH_SOURCE_DIR) + "/data/vehicles/iris.json");
  const wattswath::energy::EnergyModel model = wattswath::energy::buildModel(v, {"hover", "kinetic", "parasitic_drag"});
  const Mission m = localMission({{400, 0, 10}, {0, 0, 10}}, 0.0, 5.0);
  const AutopilotConfig ap = arduCopter32();
  PredictSettings calm;
  const MissionPrediction still = predictMission(m, v, model, ap, calm);
  PredictSettings windy;
  windy.wind = {4.0, 0.0};
  const MissionPrediction blown = predictMission(m, v, model, ap, windy);
  ASSERT_EQ(blown.breakdown.byEffect("parasitic_drag"), 0.0);
  const double wind_j = blown.breakdown.byEffect("wind");
  double expected = 0.0;
  const double k = 0.5 * v.air_density_kgpm3 * v.drag_area_m2 / v.totalEfficiency();
  for (const auto& pc : blown.pieces.pieces) {
    if (pc.phase == wattswath::energy::Phase::Ground) continue;
    // Mean air speed cubed over the piece, its ground speed along its heading (linear in time).
    for (int q = 0; q < 8; ++q) {
      const double f = (q + 0.5) / 8.0, sp = pc.v_start + (pc.v_end - pc.v_start) * f;
      const Eigen::Vector2d vg(sp * std::cos(pc.heading), sp * std::sin(pc.heading));
      expected += k * std::pow((vg - windy.wind).norm(), 3) * pc.duration / 8.0;
    }
  }
  EXPECT_NEAR(wind_j, expected, 0.02 * expected);
  EXPECT_GT(wind_j, 2.0 * still.breakdown.byEffect("parasitic_drag"));
  EXPECT_GT(blown.total.energy_j, still.total.energy_j);
  // 35 m/s against a vehicle whose drag at 30 degrees of lean caps its air speed at 9.9 m/s: it
  // never gets there, and the error says why.
  PredictSettings storm;
  storm.airframe_from_vehicle = false;
  storm.flight.airframe.drag_quadratic_per_m = kDrag;
  storm.flight.max_time_s = 600.0;
  storm.wind = {-35.0, 0.0};
  AutopilotConfig lean30 = ap;
  lean30.parameters["ANGLE_MAX"] = 3000;
  try {
    predictMission(m, v, model, lean30, storm);
    FAIL() << "a flight against a 35 m/s wind was predicted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot make way against it"), std::string::npos) << e.what();
  }
  PredictSettings gale;
  gale.wind = {45.0, 0.0};
  try {
    predictMission(m, v, model, ap, gale);
    FAIL() << "a 45 m/s wind was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("wind"), std::string::npos) << e.what();
  }
}
