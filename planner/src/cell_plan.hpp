#pragma once
// Internal to planner/src: the per-cell plan (every cell of a decomposition picks its own sweep
// angle or spiral).
#include <optional>
#include <string>
#include <vector>

#include "search_context.hpp"
#include "wattswath/energy/model.hpp"

namespace wattswath::planner::detail {

/// The per-cell plan: the area cut into geometry's boustrophedon cells at `angle` [rad] (and those
/// into convex pieces), every piece picking its own sweep angle or spiral, flown and verified over
/// `free` (see cell_plan.cpp). Pattern "spiral" when every piece is a spiral, "mixed" when some
/// are, else "boustrophedon"; the reported angle is the largest boustrophedon piece's, the
/// per-piece choices in cell_plans. `count` is increased by the routes scored; nullopt with `why`
/// set when the search cannot run.
std::optional<PlanCandidate> perCellCandidate(const Context& ctx, const energy::EnergyModel& model,
                                              const SpeedSettings& ss, RouteScorer& scorer, const StopTable& stop,
                                              const PlannerSettings& ps,
                                              const std::vector<geometry::PolygonWithHoles>& free, double angle,
                                              int* count, std::string* why);

}  // namespace wattswath::planner::detail
