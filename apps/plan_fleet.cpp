// `plan --vehicles N`: the fleet's schedule as JSON, text and report figures.
#include "plan_fleet.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

#include "wattswath/report/svg.hpp"

namespace wattswath::apps {

namespace pl = wattswath::planner;

void addSortieOptions(CLI::App* cmd, SortieRequest& req) {
  cmd->add_option("--sorties", req.sorties,
                  "split the survey into sorties that each land with the battery reserve: 'auto' (the fewest that fit, "
                  "with the least total energy among those) or a count; writes sortie_01.plan/.waypoints, ... beside mission.plan");
  cmd->add_option("--reserve", req.reserve_pct,
                  "usable battery charge to keep on landing [%] (default 25): the battery verdict of the plan, and of "
                  "each sortie with --sorties")
      ->check(CLI::Range(0.0, 90.0));
  cmd->add_option("--energy-margin", req.energy_margin_pct,
                  "the battery verdict also checks the reserve with this much more energy, for the prediction's own error "
                  "[%] (default 10, as predict's; 0: the reserve as predicted): the plan's verdict, and each sortie keeps it")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--vehicles", req.vehicles,
                  "a fleet of N vehicles flies the sorties at once (implies --sorties auto): contiguous runs of sorties per vehicle "
                  "that minimise the makespan; writes vehicle_K_sortie_NN.plan/.waypoints")
      ->check(CLI::Range(1, 100));
  struct Bounded {
    const char* name;
    double* value;
    const char* help;
    double max;
  };
  for (const Bounded& b : {Bounded{"--swap-time", &req.swap_time_s, "battery swap between two sorties of one vehicle [s] (default 120)", 86400.0},
                           Bounded{"--launch-interval", &req.launch_interval_s, "time between the fleet's first take-offs [s] (default 30)", 86400.0},
                           Bounded{"--separation", &req.separation_m,
                                   "least horizontal distance between two airborne vehicles of the fleet, checked on the flown "
                                   "trajectories; a sortie that would come closer starts later [m] (default 15)",
                                   10000.0}})
    cmd->add_option(b.name, *b.value, b.help)->check(CLI::Range(0.0, b.max));
}

pl::FleetSettings fleetSettings(const SortieRequest& req) {
  if (req.vehicles < 1 || req.vehicles > 100) throw std::invalid_argument("--vehicles " + std::to_string(req.vehicles) + ": expected 1..100");
  pl::FleetSettings s;
  s.vehicles = req.vehicles;
  s.swap_time_s = req.swap_time_s;
  s.launch_interval_s = req.launch_interval_s;
  s.separation_m = req.separation_m;
  return s;
}

nlohmann::json fleetJson(const pl::FleetSchedule& f, const SortieRequest& req, const std::vector<pl::Track>& tracks) {
  double one = 0.0;  // one vehicle flying every sortie in turn, a swap between two
  for (const auto& t : tracks) one += t.back().t;
  one += req.swap_time_s * static_cast<double>(tracks.size() - 1);
  struct Busy {
    int sorties = 0;
    double first = 1e300, last = 0.0, air = 0.0;
  };
  std::map<int, Busy> by;
  for (std::size_t i = 0; i < f.sorties.size(); ++i) {
    auto& b = by[f.sorties[i].vehicle];
    ++b.sorties;
    b.first = std::min(b.first, f.sorties[i].start_s);
    b.last = std::max(b.last, f.sorties[i].end_s);
    b.air += tracks[i].back().t;
  }
  nlohmann::json vehicles = nlohmann::json::array();
  for (const auto& [v, b] : by)
    vehicles.push_back({{"vehicle", v + 1}, {"sorties", b.sorties}, {"first_takeoff_s", b.first}, {"last_landing_s", b.last}, {"air_time_s", b.air}});
  return {{"vehicles", req.vehicles},
          {"vehicles_used", by.size()},
          {"makespan_s", f.makespan_s},
          {"one_vehicle_makespan_s", one},
          {"swap_time_s", req.swap_time_s},
          {"launch_interval_s", req.launch_interval_s},
          {"separation_m", req.separation_m},
          {"min_separation_m", std::isfinite(f.min_separation_m) ? nlohmann::json(f.min_separation_m) : nlohmann::json(nullptr)},
          {"delays", f.delays},
          {"separation_check", "horizontal distance between every two airborne vehicles on the flown trajectories (each sortie's "
                               "samples at its scheduled time, closest approach within 0.2 s steps); vehicles on the ground not counted"},
          {"schedule", vehicles}};
}

void fillFleetView(const pl::FleetSchedule& f, const SortieRequest& req, report::PlanSorties& view) {
  view.vehicles = req.vehicles;
  view.makespan_s = f.makespan_s;
  view.swap_time_s = req.swap_time_s;
  view.launch_interval_s = req.launch_interval_s;
  view.separation_m = req.separation_m;
  view.min_separation_m = f.min_separation_m;
}

void printFleet(const nlohmann::json& j) {
  const std::string least = j["min_separation_m"].is_null() ? std::string("never two airborne at once")
                                                            : report::formatNumber(j["min_separation_m"].get<double>(), 1) + " m";
  const int used = j["vehicles_used"].get<int>(), asked = j["vehicles"].get<int>();
  const std::string of = used < asked ? " of the " + std::to_string(asked) + " (one more would not finish sooner)" : "";
  std::printf("fleet: %d vehicles%s, makespan %s min:s (one vehicle flying every sortie: %s min:s), battery swap %.0f s, take-offs %.0f s apart\n",
              used, of.c_str(), report::formatMinSec(j["makespan_s"].get<double>()).c_str(),
              report::formatMinSec(j["one_vehicle_makespan_s"].get<double>()).c_str(), j["swap_time_s"].get<double>(),
              j["launch_interval_s"].get<double>());
  for (const auto& v : j["schedule"])
    std::printf("  vehicle %d: %d %s, first take-off %s, last landing %s min:s\n", v["vehicle"].get<int>(), v["sorties"].get<int>(),
                v["sorties"].get<int>() == 1 ? "sortie" : "sorties",
                report::formatMinSec(v["first_takeoff_s"].get<double>()).c_str(), report::formatMinSec(v["last_landing_s"].get<double>()).c_str());
  std::printf("  separation: at least %.1f m between airborne vehicles, checked on the flown trajectories; least found %s; %d start delay(s) of 5 s kept it\n",
              j["separation_m"].get<double>(), least.c_str(), j["delays"].get<int>());
}

}  // namespace wattswath::apps
