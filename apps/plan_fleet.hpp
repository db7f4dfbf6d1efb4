#pragma once
// `plan --sorties` and `--vehicles N` options; the sorties shared by a fleet flying at once
// (planner/fleet.hpp), as the plan's JSON, text and report show them.
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "plan_sorties.hpp"
#include "wattswath/planner/fleet.hpp"
#include "wattswath/report/reports.hpp"

namespace wattswath::apps {

/// `plan`'s options --sorties, --reserve, --vehicles, --swap-time, --launch-interval and --separation into `req`.
void addSortieOptions(CLI::App* cmd, SortieRequest& req);

/// The fleet settings of the request; throws std::invalid_argument naming the option out of range.
planner::FleetSettings fleetSettings(const SortieRequest& req);

/// The fleet's JSON ("fleet" of the sorties): makespan against one vehicle flying every sortie,
/// per-vehicle schedule, the separation kept and the least found. `tracks` are the sorties flown.
nlohmann::json fleetJson(const planner::FleetSchedule& f, const SortieRequest& req, const std::vector<planner::Track>& tracks);

/// The fleet's figures in the report's sorties section.
void fillFleetView(const planner::FleetSchedule& f, const SortieRequest& req, report::PlanSorties& view);

/// The text lines of fleetJson.
void printFleet(const nlohmann::json& fleet);

}  // namespace wattswath::apps
