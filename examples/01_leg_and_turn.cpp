// Example 1: the energy of a straight leg and of a turn, from a vehicle file.
// Usage (from the repository root): example_01_leg_and_turn [VEHICLE.json]
// Links wattswath::energy only; docs/examples.md shows the output.
#include <cmath>
#include <cstdio>
#include <string>

#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/energy/optimal_speed.hpp"
#include "wattswath/energy/profile.hpp"
#include "wattswath/energy/turns.hpp"
#include "wattswath/energy/vehicle.hpp"

namespace en = wattswath::energy;

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : "data/vehicles/iris.json";
  const en::Vehicle v = en::loadVehicle(path);  // throws naming the file and field on a bad file
  const en::ProfileLimits limits{v.max_acceleration_mps2, v.max_acceleration_mps2};
  std::printf("%s: %.2f kg, hover power %.1f W\n", v.name.c_str(), v.mass_kg, en::marinsHoverPowerW(v));

  // Marins et al.'s model: hover + kinetic + parasitic drag (+ yaw at no cost).
  const en::EnergyModel model = en::marinsModel(v);

  // A 600 m leg from rest to rest, cruising at 10 m/s: accelerate, cruise, brake pieces.
  const double distance = 600.0;
  const auto pieces = en::buildLegProfile(distance, 0.0, 10.0, 0.0, limits);
  const en::Breakdown b = model.evaluate(pieces);
  std::printf("leg %.0f m at 10 m/s: %.0f J in %.1f s (hover %.0f J, kinetic %.0f J, drag %.0f J)\n", distance,
              b.total(), b.time, b.byEffect("hover"), b.byEffect("kinetic"), b.byEffect("parasitic_drag"));
  std::printf("  by phase: accelerate %.0f J, cruise %.0f J, brake %.0f J\n", b.byPhase(en::Phase::Accelerate),
              b.byPhase(en::Phase::Cruise), b.byPhase(en::Phase::Brake));

  // The cruise speed that minimises the leg's energy, capped at the vehicle's speed limit.
  const en::CruiseSpeedOptimum best = en::optimalCruiseSpeed(model, distance, 0.0, 0.0, limits, v.max_speed_mps);
  std::printf("optimal cruise speed: %.2f m/s%s, %.0f J in %.1f s\n", best.speed,
              best.at_upper_bound ? " (the vehicle's limit)" : "", best.energy, best.time);

  // The same model from effect names (any of knownEffectNames()), searched without the limit.
  const en::EnergyModel named = en::buildModel(v, {"hover", "kinetic", "parasitic_drag"});
  const auto free = en::optimalCruiseSpeed(named, distance, 0.0, 0.0, limits, 40.0);
  std::printf("without the speed limit: %.2f m/s, %.0f J\n", free.speed, free.energy);

  // Two 100 m branches meeting at a right angle (interior angle 90 deg): stop and turn in place,
  // or fly the corner as an arc at constant speed (Marins et al. Sec. V-B).
  const double beta = M_PI / 2.0;
  const en::TurnComparison t =
      en::compareTurnStrategies(model, 100.0, beta, limits, v.max_yaw_rate_radps, v.max_speed_mps);
  std::printf("turn, stop and turn in place: %.0f J in %.1f s at %.2f m/s\n", t.sharp_stop.energy,
              t.sharp_stop.time, t.sharp_stop.speed);
  std::printf("turn, rounded (radius %.1f m): %.0f J in %.1f s at %.2f m/s\n", t.rounded.radius, t.rounded.energy,
              t.rounded.time, t.rounded.speed);
  std::printf("the rounded turn saves %.1f %%\n", t.saving_pct);
  return 0;
}
