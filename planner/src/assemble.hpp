#pragma once
// Internal to planner/src: joining per-cell candidates into one flight (GTSP order and transits).
#include <vector>

#include "search_context.hpp"
#include "wattswath/planner/order.hpp"

namespace wattswath::planner::detail {

/// Orders per-cell candidates (`g.cluster` / `g.cost` filled, one route each in `cand`) by GTSP
/// and joins them from home back to home with transits; fills res.route, res.score and res.chosen.
/// With the energy objective and `also_length_order`, the shortest order is built too and the
/// cheaper of the two kept. `exact_max_cells`: exact ordering up to this many cells.
AngleResult assemble(const Context& ctx, std::vector<Route> cand, GtspInstance g, AngleResult res, RouteScorer& scorer,
                     const StopTable& stop, Objective obj, int exact_max_cells, bool also_length_order = true);

}  // namespace wattswath::planner::detail
