// Spirals: geometry's straight-skeleton laps turned into planner routes (arcs where the footprint
// overlap allows), their start vertices, and the whole-area spiral plan.
#include "spiral_plan.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "assemble.hpp"
#include "verification.hpp"
#include "wattswath/geometry/route.hpp"

namespace wattswath::planner::detail {
namespace {

using geometry::LegRole;
using geometry::Point;
constexpr int kMaxSpiralStarts = 32;  // start vertices tried per spiral cell (evenly spread)
// [-] of the spacing: how far a spiral's rounded corner may cut inside its vertex beyond the
// footprint overlap (the outer lap's footprint covers most of the sliver; finish() checks coverage
// and takes arcs back where the plan would fall under 99 %).
constexpr double kSpiralCornerCut = 0.1;
constexpr size_t kMaxSpiralOrderCandidates = 8;  // cheapest spiral starts per cell the whole-area spiral orders
constexpr double kMaxRoundedTurn = 3.0;          // [rad] sharper corners (a spiral's out-and-back spikes) are stops

}  // namespace

Route spiralCellRoute(const Context& ctx, const geometry::SpiralCell& cell, int start, bool cw, double split_angle) {
  geometry::SpiralSettings st;
  st.spacing = ctx.problem->spacing;
  st.start_vertex = start;
  st.clockwise = cw;
  st.split_angle = split_angle;
  const auto gr = geometry::spiralRoute(cell, st);
  Route r;
  for (size_t k = 0; k < gr.points.size(); ++k) {
    if (!r.points.empty() && (gr.points[k] - r.points.back()).norm() < 1e-9) continue;
    if (r.points.empty()) {
      r.points.push_back(gr.points[k]);
      r.max_tangent.push_back(0.0);
      continue;
    }
    r.add(gr.points[k], LegRole::Sweep, 0.0);
  }
  for (size_t k = 1; k + 1 < r.points.size(); ++k) {
    const Point u = r.points[k] - r.points[k - 1], v = r.points[k + 1] - r.points[k];
    const double th = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
    r.max_tangent[k] = std::abs(th) < kMaxRoundedTurn
                           ? geometry::tangentWithin(th, ctx.overlap_margin + kSpiralCornerCut * ctx.problem->spacing)
                           : 0.0;
  }
  return r;
}

std::vector<int> spiralStarts(const geometry::SpiralCell& cell) {
  std::vector<int> out;
  if (cell.laps.empty() || cell.laps.front().empty()) return out;
  const int m = static_cast<int>(cell.laps.front().size());
  const int step = std::max(1, m / kMaxSpiralStarts);
  for (int start = 0; start < m; start += step) out.push_back(start);
  return out;
}

std::optional<AngleResult> spiralPlan(const Context& ctx, RouteScorer& scorer, const StopTable& stop, Objective obj,
                                      int exact_max_cells, double split_angle, int* count, std::string* why) {
  const auto& pr = *ctx.problem;
  const auto area = areaWithZones(pr, why);
  if (!area) {
    *why = "no spiral: " + *why;
    return std::nullopt;
  }
  std::vector<geometry::SpiralCell> cells;
  try {
    cells = geometry::decomposeSpiral(*area, pr.spacing, split_angle);
  } catch (const std::exception& e) {
    *why = std::string("no spiral: ") + e.what();
    return std::nullopt;
  }
  std::vector<Route> cand;
  GtspInstance g;
  int cluster = 0;
  for (const auto& cell : cells) {
    // Every start vertex and direction ranked by the quick estimate (or length); the best few are
    // scored exactly and go to the order search (each candidate kept multiplies its work).
    std::vector<std::pair<double, Route>> ranked;
    for (int start : spiralStarts(cell))
      for (bool cw : {false, true}) {
        Route r = spiralCellRoute(ctx, cell, start, cw, split_angle);
        if (r.points.size() < 2) continue;
        ++*count;
        const double estimate = obj == Objective::Length ? r.length() : stopEstimate(r, stop, scorer);
        if (std::isfinite(estimate)) ranked.emplace_back(estimate, std::move(r));
      }
    std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    if (ranked.size() > kMaxSpiralOrderCandidates) ranked.resize(kMaxSpiralOrderCandidates);
    bool any = false;
    for (auto& [estimate, r] : ranked) {
      const double cost = obj == Objective::Length ? estimate : scorer.energy(r);
      if (!std::isfinite(cost)) continue;
      cand.push_back(std::move(r));
      g.cluster.push_back(cluster);
      g.cost.push_back(cost);
      any = true;
    }
    cluster += any;
  }
  if (cand.empty()) {
    *why = "no spiral: the area is narrower than one swath";
    return std::nullopt;
  }
  AngleResult res;
  res.angle = split_angle;
  res.cells = cluster;
  return assemble(ctx, std::move(cand), std::move(g), res, scorer, stop, obj, exact_max_cells);
}

SpiralStage spiralStage(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                        const StopTable& stop, const PlannerSettings& ps,
                        const std::vector<geometry::PolygonWithHoles>& free, double split_angle) {
  SpiralStage out;
  RouteScorer local(model, ss);
  const auto s = spiralPlan(ctx, local, stop, Objective::Energy, ps.exact_max_cells, split_angle, &out.count, &out.why);
  if (s && std::isfinite(s->score)) {
    out.plan = finish(free, ctx.problem->footprint, local, *s, "spiral");
  } else if (out.why.empty()) {
    out.why = "no spiral: no start vertex gave a flyable route";
  }
  return out;
}

}  // namespace wattswath::planner::detail
