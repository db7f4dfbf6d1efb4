#pragma once
// Internal to planner/src: the one-angle search (boustrophedon over the whole area at one sweep
// angle, coarse then refined) and the choice among its best angles flown in full.
#include <vector>

#include "search_context.hpp"
#include "wattswath/energy/model.hpp"

namespace wattswath::planner::detail {

/// Boustrophedon at `angle` [rad]: cells, 4 candidates each, ordered by GTSP, assembled home to
/// home (with the shortest order too when `also_length_order`, see assemble()).
AngleResult evaluateAngle(const Context& ctx, double angle, RouteScorer& scorer, const StopTable& stop, Objective obj,
                          int exact_max_cells, bool also_length_order = false);

/// Coarse grid over [0, 180) then a fine grid around the best coarse angles: every evaluated angle
/// (coarse and refined), best score first. `count` is increased by the angles evaluated; `scan`,
/// when given, receives every angle's score, by angle.
std::vector<AngleResult> searchAngles(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                                      const StopTable& stop, Objective obj, const PlannerSettings& ps, int* count,
                                      std::vector<AngleScore>* scan = nullptr);

/// The one-angle plan: the best-ranked angles of `ranked` re-assembled (also with the shortest
/// order, and with one sweep line fewer than full coverage needs where that may keep coverage),
/// flown on ps.threads workers and checked for coverage lazily, cheapest first; the cheapest that
/// keeps coverage (else the best by better()). Invalid when no angle has a route. `neighbour`,
/// when given, receives the plan's angle with the other line count (when one was built).
PlanCandidate bestAnglePlan(const Context& ctx, const std::vector<AngleResult>& ranked, const energy::EnergyModel& model,
                            const SpeedSettings& ss, RouteScorer& scorer, const StopTable& stop,
                            const PlannerSettings& ps, const std::vector<geometry::PolygonWithHoles>& free,
                            LineCountNeighbour* neighbour = nullptr);

}  // namespace wattswath::planner::detail
