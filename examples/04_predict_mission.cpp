// Example 4: predict a mission file: how long, how much energy, and does it fit the battery,
// as the vehicle's autopilot will fly it (what `wattswath predict` does).
// Usage (from the repository root): example_04_predict_mission [MISSION.plan|.waypoints] [VEHICLE.json]
// Links wattswath::mission; docs/examples.md shows the output.
#include <cstdio>
#include <string>

#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/vehicle.hpp"
#include "wattswath/mission/autopilot.hpp"
#include "wattswath/mission/files.hpp"
#include "wattswath/mission/predict.hpp"

namespace en = wattswath::energy;
namespace ms = wattswath::mission;

int main(int argc, char** argv) {
  const std::string mission_path = argc > 1 ? argv[1] : "tests/data/good/mission_survey.plan";
  const std::string vehicle_path = argc > 2 ? argv[2] : "data/vehicles/iris-plus-arducopter3.json";

  // The mission file (throws MissionError naming the item and field it cannot load).
  const ms::Mission m = ms::readMission(mission_path);
  std::printf("mission: %s file, %zu items, home %.6f N, %.6f E\n", m.format.c_str(), m.items.size(),
              m.home.lat_deg, m.home.lon_deg);

  // The vehicle, its autopilot (firmware, version, parameters) and an energy model of named effects.
  const en::Vehicle v = en::loadVehicle(vehicle_path);
  const ms::AutopilotConfig ap = ms::parseAutopilot(v.autopilot_json, vehicle_path);
  const en::EnergyModel model = en::buildModel(v, {"hover", "kinetic", "parasitic_drag"});
  std::printf("vehicle: %s, autopilot %s %s (%s model)\n", v.name.c_str(), ap.firmware.c_str(),
              ap.version.c_str(), ms::toString(ap.family));

  ms::PredictSettings settings;
  settings.reserve_fraction = 0.25;  // keep a quarter of the usable charge on landing
  const ms::MissionPrediction p = ms::predictMission(m, v, model, ap, settings);
  std::printf("total: %.0f s (%d min %02d s), %.0f J (%.2f Wh), %.0f m\n", p.total.time_s, int(p.total.time_s) / 60,
              int(p.total.time_s) % 60, p.total.energy_j, p.total.energy_j / 3600.0, p.total.distance_m);
  for (int i = 0; i < ms::kFlightPhaseCount; ++i) {
    const ms::Totals& t = p.phases[i];
    std::printf("  %-8s %6.0f s %8.0f J %7.0f m\n", ms::toString(static_cast<ms::FlightPhase>(i)), t.time_s,
                t.energy_j, t.distance_m);
  }
  if (p.battery.known)
    std::printf("battery: %.0f %% of the usable charge left on landing; %s\n", 100.0 * p.battery.usable_left_end,
                p.battery.verdict.c_str());
  else
    std::printf("battery: unknown (the vehicle file has none)\n");
  std::printf("model: %s\n", p.flight.model.c_str());
  for (const auto& w : p.warnings) std::printf("warning: %s\n", w.c_str());

  // The same mission in a steady 6 m/s wind from the east (the air moving west): the vehicle flies
  // against its drag at air speed and the energy model's drag is taken at air speed.
  settings.wind = {-6.0, 0.0};  // [m/s] east, north: where the air moves to
  const ms::MissionPrediction windy = ms::predictMission(m, v, model, ap, settings);
  std::printf("in 6 m/s from the east: %.0f s, %.0f J (%+.1f %%)\n", windy.total.time_s, windy.total.energy_j,
              100.0 * (windy.total.energy_j / p.total.energy_j - 1.0));
  return 0;
}
