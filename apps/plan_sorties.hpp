#pragma once
// `plan --sorties auto|N --reserve PCT`: the plan split into battery-sized sorties
// (planner/sorties.hpp), each written as its own mission and checked with the flight model: a
// sortie that does not land with the reserve shrinks the budget and the split is redone.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plan_flight.hpp"
#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/flight_score.hpp"
#include "wattswath/report/reports.hpp"

namespace wattswath::apps {

/// What the user asked for.
struct SortieRequest {
  std::string sorties;       ///< "auto" or a count (empty: no split)
  double reserve_pct = 25.0; ///< [%] usable charge to keep on landing
  double energy_margin_pct = 10.0;  ///< [%] extra energy each sortie must keep the reserve with too (predict's --energy-margin)
  int vehicles = 0;          ///< [-] fleet flying the sorties at once (0: no fleet)
  double swap_time_s = 120.0;       ///< [s] battery swap on the ground between two sorties of a vehicle
  double launch_interval_s = 30.0;  ///< [s] between the vehicles' first take-offs
  double separation_m = 15.0;       ///< [m] least horizontal distance between airborne vehicles
  bool force = false;               ///< replace existing sortie files (--force); never an input
  std::vector<std::string> inputs;  ///< the run's input files, which no sortie file may overwrite
};

/// The split's summary (JSON) and what the plan report draws of it.
struct SortieOutcome {
  nlohmann::json json;           ///< counts, energies, per sortie, fleet schedule
  report::PlanSorties view;      ///< the report's sorties section
  std::vector<std::string> files;  ///< the file names written into the output folder
};

/// The sortie files in `dir` (`sortie_NN.plan` / `.waypoints`, `vehicle_K_sortie_NN.*`, as
/// planSorties names them) that are not among `written` nor one of the run's `inputs`: left by an
/// earlier run.
std::vector<std::string> staleSortieFiles(const std::filesystem::path& dir, const std::vector<std::string>& written,
                                          const std::vector<std::string>& inputs);

/// Splits `plan` (the plan written, `flight` its one flight by the autopilot model, whose take-off
/// and landing every sortie repeats) for the vehicle's battery, writes
/// `sortie_NN.plan` / `.waypoints` into `dir` (with a fleet `vehicle_K_sortie_NN.*`, the fleet
/// scheduled by planner::scheduleFleet on the flown trajectories) and returns the summary. `scoring` as for flyFinalists (with
/// `arc_waypoints` in its mission options as chosen). Throws std::runtime_error when the vehicle
/// has no battery or no split fits.
SortieOutcome planSorties(const planner::PlanCandidate& plan, const PlanFlight& flight, planner::FlightScoring scoring, const std::string& vehicle_path, const SortieRequest& req,
                           const std::filesystem::path& dir);

/// The text lines of planSorties' summary.
void printSorties(const nlohmann::json& j);

}  // namespace wattswath::apps
