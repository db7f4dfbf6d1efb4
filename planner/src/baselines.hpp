#pragma once
// Internal to planner/src: what the plan is measured against: the shortest-path and ground-station
// baselines, scored by the same model, and the physical lower bound.
#include <vector>

#include "search_context.hpp"
#include "wattswath/energy/model.hpp"

namespace wattswath::planner::detail {

/// Baseline (a), the shortest path: length objective for angle and order, flown with our speeds
/// (`scorer`), coverage checked over `free` (taken from a candidate of `checked` that flies the same
/// path, see finish()). `count` is increased by the angles evaluated.
PlanCandidate shortestPathBaseline(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                                   RouteScorer& scorer, const StopTable& stop, const PlannerSettings& ps,
                                   const std::vector<geometry::PolygonWithHoles>& free, int* count,
                                   const std::vector<const PlanCandidate*>& checked = {});

/// Baseline (b), the ground-station default: sweep parallel to the longest edge of the outer
/// boundary, one constant speed (ps.ground_station_speed, capped), a stop at every corner.
/// `count` is increased by one. `checked` as for shortestPathBaseline.
PlanCandidate groundStationBaseline(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                                    const StopTable& stop, const PlannerSettings& ps,
                                    const std::vector<geometry::PolygonWithHoles>& free, int* count,
                                    const std::vector<const PlanCandidate*>& checked = {});

/// Physical lower bound on the energy of any flight covering `problem` [J]: the swath length the
/// coverage needs at the best energy per metre plus the way from home to the area and back, and,
/// for speed-only models, the best single stop-to-stop leg of that length.
double lowerBound(const SurveyProblem& problem, const energy::EnergyModel& model, const SpeedSettings& ss,
                  RouteScorer& scorer, const PlannerSettings& ps);

}  // namespace wattswath::planner::detail
