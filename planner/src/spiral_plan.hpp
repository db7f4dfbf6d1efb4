#pragma once
// Internal to planner/src: spiral routes (geometry's straight-skeleton laps as planner routes) and
// the whole-area spiral plan.
#include <optional>
#include <string>
#include <vector>

#include "search_context.hpp"
#include "wattswath/energy/model.hpp"
#include "wattswath/geometry/coverage.hpp"

namespace wattswath::planner::detail {

/// One spiral cell flown from `start` (a vertex of its first lap) in direction `cw`, as a planner
/// route: all segments Sweep, arcs allowed at corners within the footprint overlap, none at the
/// out-and-back spikes. `split_angle` [rad] as in geometry::SpiralSettings.
Route spiralCellRoute(const Context& ctx, const geometry::SpiralCell& cell, int start, bool cw, double split_angle);

/// Start vertices tried on a spiral cell: every vertex of its first lap, at most 32 evenly spread.
std::vector<int> spiralStarts(const geometry::SpiralCell& cell);

/// Spiral plan: geometry's straight-skeleton spirals (an area with holes is first cut into hole-free
/// boustrophedon pieces at `split_angle` [rad]; narrow necks split laps into further cells).
/// Candidates of each spiral cell: every start vertex of spiralStarts(), both directions; then GTSP
/// order and transits as for boustrophedon. `count` is increased by the routes scored; nullopt with
/// `why` set when there is no spiral.
std::optional<AngleResult> spiralPlan(const Context& ctx, RouteScorer& scorer, const StopTable& stop, Objective obj,
                                      int exact_max_cells, double split_angle, int* count, std::string* why);

/// The spiral stage: the best whole-area spiral, flown and verified.
struct SpiralStage {
  std::optional<PlanCandidate> plan;  ///< the spiral plan, absent when there is none
  std::string why;                    ///< why there is none ("no spiral: ...")
  int count = 0;                      ///< routes scored
};

/// Runs the spiral stage with its own scorer (so its numbers do not depend on the number of
/// threads): spiralPlan() split at `split_angle` [rad], finished (coverage checked) over `free`.
SpiralStage spiralStage(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                        const StopTable& stop, const PlannerSettings& ps,
                        const std::vector<geometry::PolygonWithHoles>& free, double split_angle);

}  // namespace wattswath::planner::detail
