// The finalists flown by the autopilot model (flight_score.hpp): a mission whose .plan text another
// finalist already wrote is flown once and gets that flight, and the number of threads the flights
// run on changes no number.
#include <gtest/gtest.h>

#include <memory>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/flight_score.hpp"
#include "mission_fixtures.hpp"
#include "test_util.hpp"

using namespace wattswath;
using namespace wattswath::planner;

namespace {

// An area planned for a vehicle, with the flight scoring `plan` would use (addresses stable).
struct Planned {
  geometry::SurveyArea area;
  SurveyProblem pr;
  energy::Vehicle v;
  energy::EnergyModel model;
  PlanResult r;
  FlightScoring s;
};

std::unique_ptr<Planned> planned(const std::string& area_file, double spacing, const std::string& vehicle_file) {
  auto p = std::make_unique<Planned>();
  p->area = geometry::readSurveyArea(test::sourcePath(area_file));
  if (!p->area.frame) throw std::runtime_error(area_file + ": no frame");
  p->pr = test::problemOf(p->area, spacing);
  p->v = energy::loadVehicle(test::sourcePath(vehicle_file));
  p->model = energy::marinsModel(p->v);
  p->r = planCoverage(p->pr, p->v, p->model);
  p->s.problem = &p->pr;
  p->s.frame = &*p->area.frame;
  p->s.vehicle = &p->v;
  p->s.model = &p->model;
  return p;
}

}  // namespace

TEST(FlightScore, TheSameMissionTwiceIsOneFlightAndThreadsChangeNoNumber) {
  const auto p = planned("data/areas/espiral_rectangle.geojson", 21.45, "data/vehicles/iris.json");
  const PlanResult& r = p->r;
  FlightScoring s = p->s;
  ASSERT_TRUE(r.plan.valid);
  ASSERT_TRUE(r.ground_station_default.valid);
  s.as_written = {&r.ground_station_default};  // a baseline, as plan flies it: one row
  const PlanCandidate copy = r.plan;  // another finalist flying the very same route
  const std::vector<std::pair<std::string, const PlanCandidate*>> cands = {
      {"plan", &r.plan}, {"ground-station default", &r.ground_station_default}, {"copy", &copy}};
  s.threads = 1;
  const auto one = scoreByFlight(cands, s);
  s.threads = 2;
  const auto two = scoreByFlight(cands, s);
  ASSERT_EQ(one.size(), two.size());
  ASSERT_GE(one.size(), 3u);
  for (std::size_t i = 0; i < one.size(); ++i) {
    SCOPED_TRACE(one[i].label);
    EXPECT_EQ(one[i].label, two[i].label);  // the order of the candidates, whatever thread flew them
    EXPECT_EQ(one[i].prediction.total.energy_j, two[i].prediction.total.energy_j);
    EXPECT_EQ(one[i].prediction.total.time_s, two[i].prediction.total.time_s);
    // Each flight is the one flyWrittenMission gives for its own mission (predict's numbers).
    const auto alone = flyWrittenMission(one[i].mission, s, one[i].label);
    EXPECT_EQ(one[i].prediction.total.energy_j, alone.total.energy_j);
    EXPECT_EQ(one[i].prediction.total.time_s, alone.total.time_s);
  }
  // The copy's rows (the last ones) repeat the plan's flights exactly.
  // Rows per route candidate: 1, or 2 with arcs, each also with its speeds a waypoint early.
  std::size_t per = 0;
  while (per < one.size() && one[per].candidate == &r.plan) ++per;
  ASSERT_EQ(one.size(), 2 * per + 1);
  for (std::size_t k = 0; k < per; ++k) {
    EXPECT_EQ(one[k].candidate, &r.plan);
    EXPECT_EQ(one[per + 1 + k].candidate, &copy);
    EXPECT_EQ(mission::toQgcPlan(one[k].mission.mission), mission::toQgcPlan(one[per + 1 + k].mission.mission));
    EXPECT_EQ(one[k].prediction.total.energy_j, one[per + 1 + k].prediction.total.energy_j);
  }
  EXPECT_GT(one[per].prediction.total.energy_j, one[0].prediction.total.energy_j);  // the baseline flies dearer
}

TEST(FlightScore, ForArduCopterBefore41SpeedCommandsAWaypointEarlyAreOfferedAndFlyTheSweepsAtSpeed) {
  // ArduCopter 3.x flies a speed increase only from the next waypoint on, so a mission that slows
  // for each turn flies every following sweep at the turn's speed. For the leash family each
  // finalist is also written with each speed command the faster of its leg's and the next leg's;
  // on the IRIS+ area at 15 m spacing that flight is over a quarter shorter (142 -> 96 kJ when
  // written). ArduCopter 4.1+ gets the variant too (its next leg is planned before the command
  // runs: FlightScore.ForArduCopter41AndLater...); PX4, which applies a speed at once, does not.
  const auto p = planned("data/areas/iris_area.geojson", 15.0, "data/vehicles/iris-plus-arducopter3.json");
  const PlanResult& r = p->r;
  ASSERT_TRUE(r.plan.valid);
  FlightScoring s = p->s;
  setAutopilot(s, mission::parseAutopilot(p->v.autopilot_json, p->v.name));
  ASSERT_EQ(s.autopilot.family, mission::AutopilotFamily::ArduCopterLeash);
  const auto scores = scoreByFlight({{"plan", &r.plan}}, s);
  const FlightScore* late = nullptr;
  const FlightScore* early = nullptr;
  for (const auto& f : scores) {
    if (f.arc_waypoints) continue;
    (f.speeds_a_waypoint_early ? early : late) = &f;
  }
  ASSERT_TRUE(late && early);
  EXPECT_NE(early->label.find("speeds a waypoint early"), std::string::npos);
  const auto& a = late->mission.mission.waypoints;
  const auto& b = early->mission.mission.waypoints;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_DOUBLE_EQ(b[i].speed_mps, i + 1 < a.size() ? std::max(a[i].speed_mps, a[i + 1].speed_mps) : a[i].speed_mps) << i;
  EXPECT_LT(early->prediction.total.time_s, 0.8 * late->prediction.total.time_s);
  EXPECT_LT(early->prediction.total.energy_j, 0.8 * late->prediction.total.energy_j);
  // An autopilot that applies a speed at once: no variant.
  setAutopilot(s, mission::parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test"));
  for (const auto& f : scoreByFlight({{"plan", &r.plan}}, s)) EXPECT_FALSE(f.speeds_a_waypoint_early) << f.label;
}

TEST(FlightScore, ForArduCopter41AndLaterSpeedCommandsAWaypointEarlySpareTheSweepsASecondAcceleration) {
  // ArduCopter 4.1+ plans the leg after a waypoint it flies through when that waypoint starts, with
  // the speed then in force; the DO_CHANGE_SPEED before the next waypoint runs only when this one
  // is reached, and re-plans the leg in flight: a sweep after a slow turn first accelerates to the
  // turn's speed, then again to its own (SCurve::set_speed_max). Written a waypoint early, the
  // sweep's speed is in force when its leg is planned: on the IRIS+ area at 15 m with the 4.5
  // defaults the written mission flies 4-5 % shorter (87.4 -> 83.2 kJ, 6:26 -> 6:05).
  const auto p = planned("data/areas/iris_area.geojson", 15.0, "data/vehicles/iris.json");
  const PlanResult& r = p->r;
  ASSERT_TRUE(r.plan.valid);
  FlightScoring s = p->s;
  ASSERT_EQ(s.autopilot.family, mission::AutopilotFamily::ArduCopterSCurve);
  const FlightScore* late = nullptr;
  const FlightScore* early = nullptr;
  const auto scores = scoreByFlight({{"plan", &r.plan}}, s);
  for (const auto& f : scores) {
    if (f.arc_waypoints) continue;
    (f.speeds_a_waypoint_early ? early : late) = &f;
  }
  ASSERT_TRUE(late && early);
  EXPECT_LT(early->prediction.total.time_s, 0.96 * late->prediction.total.time_s);
  EXPECT_LT(early->prediction.total.energy_j, 0.97 * late->prediction.total.energy_j);
  EXPECT_EQ(scores[cheapestFlight(scores)].speeds_a_waypoint_early, true);
}

// PX4 switches to the next waypoint within the item's acceptance radius, NAV_ACC_RAD (10 m) when the
// item gives none, so a survey written without one would end its sweeps up to 9 m short of the edge
// (median 6 m on this area). Every waypoint of a PX4 mission carries kPx4AcceptanceRadius in
// param2, and the PX4-flown plan passes within that of each; ArduCopter's missions leave it 0.
TEST(FlightScore, APx4MissionNamesItsAcceptanceRadiusAndItsFlightPassesEveryWaypoint) {
  const auto p = planned("data/areas/iris_area.geojson", 15.0, "data/vehicles/iris.json");
  const PlanResult& r = p->r;
  ASSERT_TRUE(r.plan.valid);
  FlightScoring s = p->s;
  setAutopilot(s, mission::parseAutopilot(R"({"firmware":"PX4","version":"1.14"})", "test"));
  const auto scores = scoreByFlight({{"plan", &r.plan}}, s);
  ASSERT_FALSE(scores.empty());
  const FlightScore& f = scores.front();
  const geometry::LocalFrame frame(f.mission.mission.home);  // the prediction's frame: home at the origin
  for (const auto& w : f.mission.mission.waypoints) {
    EXPECT_EQ(w.acceptance_radius_m, kPx4AcceptanceRadius);
    const geometry::Point at = frame.toLocal(w.position.lat_deg, w.position.lon_deg);
    double closest = 1e9;
    for (const auto& smp : f.prediction.flight.samples) closest = std::min(closest, (smp.position.head<2>() - at).norm());
    EXPECT_LT(closest, kPx4AcceptanceRadius) << w.position.lat_deg << ", " << w.position.lon_deg;
  }
  // ... and the .plan carries it where QGroundControl and PX4 read it: NAV_WAYPOINT param2.
  int waypoints = 0;
  const nlohmann::json plan = nlohmann::json::parse(mission::toQgcPlan(f.mission.mission));
  for (const auto& item : plan["mission"]["items"])
    if (item["command"] == 16) {
      EXPECT_EQ(item["params"][1].get<double>(), kPx4AcceptanceRadius);
      ++waypoints;
    }
  EXPECT_EQ(waypoints, static_cast<int>(f.mission.mission.waypoints.size()));
  setAutopilot(s, mission::parseAutopilot(R"({"firmware":"ArduCopter","version":"4.5"})", "test"));
  const auto ardupilot = scoreByFlight({{"plan", &r.plan}}, s);  // kept: the loop reads into it
  for (const auto& w : ardupilot.front().mission.mission.waypoints) EXPECT_EQ(w.acceptance_radius_m, 0.0);
  EXPECT_FALSE(ardupilot.front().mission.mission.repeat_first_speed_change);
  EXPECT_FALSE(f.mission.mission.repeat_first_speed_change);  // PX4
}

TEST(FlightScore, ForArduCopter41To44TheFirstSpeedChangeIsWrittenTwice) {
  // ArduCopter 4.1-4.4 drops the first DO item after the take-off when it is a speed change
  // (issue 21080): for those versions the mission repeats it, so the first leg flies as scored.
  const auto p = planned("data/areas/iris_area.geojson", 15.0, "data/vehicles/iris.json");
  ASSERT_TRUE(p->r.plan.valid);
  FlightScoring s = p->s;
  setAutopilot(s, mission::parseAutopilot(R"({"firmware":"ArduCopter","version":"4.3"})", "test"));
  const auto scores = scoreByFlight({{"plan", &p->r.plan}}, s);
  ASSERT_FALSE(scores.empty());
  EXPECT_TRUE(scores.front().mission.mission.repeat_first_speed_change);
  for (const auto& n : scores.front().prediction.warnings) EXPECT_EQ(n.find("drops a DO_CHANGE_SPEED"), std::string::npos) << n;
}
