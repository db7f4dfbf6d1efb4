#pragma once
// `plan --sorties auto|N --reserve PCT`: the plan split into battery-sized sorties
// (planner/sorties.hpp), each written as its own mission and checked with the flight model: a
// sortie that does not land with the reserve shrinks the budget and the split is redone.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "wattswath/planner/coverage.hpp"
#include "wattswath/planner/flight_score.hpp"

namespace wattswath::apps {

/// What the user asked for.
struct SortieRequest {
  std::string sorties;       ///< "auto" or a count (empty: no split)
  double reserve_pct = 25.0; ///< [%] usable charge to keep on landing
};

/// Splits `plan` (the plan written, flown as `single_flight_j` [J] in one flight by the autopilot
/// model; `overhead_j` [J] its take-off and landing) for the vehicle's battery, writes
/// `sortie_NN.plan` / `.waypoints` into `dir` and returns the JSON summary. `scoring` as for flyFinalists (with
/// `arc_waypoints` in its mission options as chosen). Throws std::runtime_error when the vehicle
/// has no battery or no split fits.
nlohmann::json planSorties(const planner::PlanCandidate& plan, double single_flight_j, double overhead_j,
                           planner::FlightScoring scoring, const std::string& vehicle_path, const SortieRequest& req,
                           const std::filesystem::path& dir);

/// The text lines of planSorties' summary.
void printSorties(const nlohmann::json& j);

}  // namespace wattswath::apps
