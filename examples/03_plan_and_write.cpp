// Example 3: plan the minimum-energy coverage of an area, fly its mission with the vehicle's
// autopilot model in each way it can be written, and write the cheapest as a QGroundControl .plan
// file (what `wattswath plan` does for the search's choice, without the reports).
// Usage (from the repository root): example_03_plan_and_write [AREA] [VEHICLE.json] [OUT.plan]
// Links wattswath::planner; docs/examples.md shows the output.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "wattswath/energy/model.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/geometry/survey_area.hpp"
#include "wattswath/mission/planned_mission.hpp"
#include "wattswath/mission/autopilot.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/flight_score.hpp"
#include "wattswath/planner/mission_from_plan.hpp"

namespace en = wattswath::energy;
namespace geo = wattswath::geometry;
namespace pl = wattswath::planner;

int main(int argc, char** argv) {
  const std::string area_path = argc > 1 ? argv[1] : "data/areas/iris_area.geojson";
  const std::string vehicle_path = argc > 2 ? argv[2] : "data/vehicles/iris.json";
  const std::string out = argc > 3 ? argv[3]
                                   : (std::filesystem::temp_directory_path() / "wattswath_example_03.plan").string();

  const en::Vehicle vehicle = en::loadVehicle(vehicle_path);
  const geo::SurveyArea area = geo::readSurveyArea(area_path);
  if (!area.frame) throw std::runtime_error(area_path + ": no geodetic frame, a mission needs lat/lon");

  // The problem in the area's local frame [m]: 15 m between lines, 10 m above home.
  pl::SurveyProblem problem;
  problem.area = area.polygon();
  problem.no_fly = area.no_fly;
  problem.home = area.home ? *area.home : problem.area.outer.front();
  problem.spacing = problem.footprint = 15.0;
  problem.altitude = 10.0;

  // Scored by Marins et al.'s model; the planner searches angles, patterns, order, corners and speeds.
  const en::EnergyModel model = en::marinsModel(vehicle);
  const pl::PlanResult r = pl::planCoverage(problem, vehicle, model);
  const pl::PlanCandidate& plan = r.plan;
  std::printf("plan: %s at %.0f deg, %d cell(s), %.0f m, %.0f s, %.0f J (%.2f Wh)\n", plan.pattern.c_str(),
              plan.sweep_angle_deg, plan.cells, plan.flown.length, plan.flown.time, plan.flown.energy,
              plan.flown.energy / 3600.0);
  std::printf("coverage %.1f %%, lower bound %.0f J, %d candidates scored\n", plan.coverage_pct, r.lower_bound_j,
              r.candidates);
  std::printf("baselines: shortest path %.0f J, ground-station default %.0f J\n", r.shortest_path.flown.energy,
              r.ground_station_default.flown.energy);

  // Waypoints and speed commands of the plan, converted to WGS84 by the area's frame, flown by the
  // vehicle's autopilot model (its autopilot object, else ArduCopter 4.5 defaults) as written and,
  // for ArduCopter, with each speed command a waypoint early; the cheapest flight is written.
  pl::FlightScoring scoring;
  scoring.problem = &problem;
  scoring.frame = &*area.frame;
  scoring.home_altitude_amsl_m = area.home_alt_m.value_or(area.frame->origin().alt_m);
  scoring.vehicle = &vehicle;
  scoring.model = &model;
  pl::setAutopilot(scoring, wattswath::mission::parseAutopilot(vehicle.autopilot_json, vehicle.name));
  const auto flights = pl::scoreByFlight({{"plan", &plan}}, scoring);
  for (const auto& f : flights)
    std::printf("flown: %s, %.0f J, %.0f s\n", f.label.c_str(), f.prediction.total.energy_j, f.prediction.total.time_s);
  const pl::FlightScore& best = flights[pl::cheapestFlight(flights)];
  const pl::PlanMission& pm = best.mission;
  for (const auto& note : pm.notes) std::printf("note: %s\n", note.c_str());
  const std::string text = wattswath::mission::toQgcPlan(pm.mission);
  const auto problems = wattswath::mission::checkQgcPlan(text);  // empty: QGroundControl loads it
  std::ofstream(out) << text;
  std::printf("mission (%s): %zu waypoints, QGroundControl check %s; wrote %s\n", best.label.c_str(), pm.mission.waypoints.size(),
              problems.empty() ? "passed" : problems.front().c_str(),
              std::filesystem::path(out).filename().string().c_str());
  return problems.empty() ? 0 : 1;
}
