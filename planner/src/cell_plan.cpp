// The per-cell plan: the area cut into boustrophedon cells (and those into convex pieces), every
// piece offering boustrophedon routes at its own best angle (each start corner) and spirals (each
// start vertex, both ways), one GTSP per partition picking a candidate per piece and the order.
#include "cell_plan.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "assemble.hpp"
#include "spiral_plan.hpp"
#include "verification.hpp"
#include "wattswath/geometry/coverage.hpp"

namespace wattswath::planner::detail {
namespace {

using geometry::Ring;
constexpr size_t kMaxSpiralKeep = 6;     // cheapest spiral candidates a cell keeps for the order search
constexpr size_t kMaxConvexPieces = 6;   // a cell is cut into convex pieces only when there are at most this many
constexpr double kKeepWithin = 1.10;     // a piece keeps alternatives costing at most this times its best

// A per-cell candidate of the mixed search.
struct CellCandidate {
  Route route;
  double cost = kInf;  // [J] energy of the route alone
  bool spiral = false;
  double angle = 0.0;  // [rad] sweep angle (boustrophedon)
};

// Boustrophedon route over the single cell of `cctx` at `angle`, first row at the top or bottom,
// first pass starting at the right or left. Where the cell is not monotone at this angle its sweep
// intervals form several sub-cells: they are flown in line order (from the top when `top`), each
// from the corner nearest the previous one's exit.
Route sweepCellRoute(const Context& cctx, double angle, bool top, bool right) {
  double first_y = 0.0;
  auto sub = sweepCells(cctx, angle, &first_y);
  if (sub.empty()) return {};
  std::stable_sort(sub.begin(), sub.end(), [top](const geometry::SweepLineCell& a, const geometry::SweepLineCell& b) {
    return top ? a.first_line > b.first_line : a.first_line < b.first_line;
  });
  Route r = cellRoute(cctx, sub.front(), angle, first_y, top, right);
  for (size_t k = 1; k < sub.size(); ++k) {
    Route best;
    double best_d = kInf;
    for (int t = 0; t < 2; ++t)
      for (bool rt : {false, true}) {
        Route c = cellRoute(cctx, sub[k], angle, first_y, t == 1, rt);
        if (c.points.empty()) continue;
        const double d = (c.points.front() - r.points.back()).norm();
        if (d < best_d) {
          best_d = d;
          best = std::move(c);
        }
      }
    if (best.points.empty()) continue;
    if (r.points.empty()) {
      r = std::move(best);
      continue;
    }
    appendVia(cctx, r, best);
  }
  return r;
}

// The cell's sweep angle [rad] by the estimate (one start corner): coarse, then refined around the
// coarse best; `decomposition_angle` when no angle gives a route.
double bestCellAngle(const Context& cctx, double decomposition_angle, const PlannerSettings& ps, RouteScorer& scorer,
                     const StopTable& stop, int* count) {
  double best_angle = decomposition_angle, best_estimate = kInf;
  auto consider = [&](double a) {
    const Route r = sweepCellRoute(cctx, a, false, false);
    ++*count;
    if (r.points.size() < 2) return;
    const double e = stopEstimate(r, stop, scorer);
    if (e < best_estimate) {
      best_estimate = e;
      best_angle = a;
    }
  };
  for (double a = 0.0; a < 180.0 - 1e-9; a += ps.coarse_step_deg) consider(a * kDeg);
  const double coarse_best = best_angle;
  for (double da = -ps.coarse_step_deg + ps.fine_step_deg; da < ps.coarse_step_deg - 1e-9; da += ps.fine_step_deg)
    if (std::abs(da) > 1e-9) consider(coarse_best + da * kDeg);
  return best_angle;
}

// Boustrophedon candidates of the cell of `cctx`, scored exactly with each start corner at the
// cell's best angle, and at the decomposition's angle unless clearly dearer.
std::vector<CellCandidate> boustrophedonCandidates(const Context& cctx, double decomposition_angle,
                                                   const PlannerSettings& ps, RouteScorer& scorer,
                                                   const StopTable& stop, int* count) {
  std::vector<CellCandidate> out;
  auto corners = [&](double angle) {
    for (int top = 0; top < 2; ++top)
      for (bool right : {false, true}) {
        CellCandidate c;
        c.route = sweepCellRoute(cctx, angle, top == 1, right);
        c.angle = angle;
        if (c.route.points.size() < 2) continue;
        c.cost = scorer.energy(c.route);
        ++*count;
        if (std::isfinite(c.cost)) out.push_back(std::move(c));
      }
  };
  const double best_angle = bestCellAngle(cctx, decomposition_angle, ps, scorer, stop, count);
  corners(best_angle);
  if (std::abs(normDeg(best_angle) - normDeg(decomposition_angle)) > 1e-6) {
    // The decomposition's angle too (its corners line up with the neighbouring cells'), unless
    // clearly dearer: every candidate kept multiplies the order search's work.
    double best_cost = kInf;
    for (const auto& c : out) best_cost = std::min(best_cost, c.cost);
    const size_t before = out.size();
    corners(decomposition_angle);
    double alt = kInf;
    for (size_t i = before; i < out.size(); ++i) alt = std::min(alt, out[i].cost);
    if (alt > kKeepWithin * best_cost) out.resize(before);
  }
  return out;
}

// The spirals of `spirals` (the spiral cells of one piece, split by necks) flown one after the
// other: the first from `start` in direction `cw`, each next from its first-lap vertex nearest
// the previous exit.
Route chainedSpiralRoute(const Context& cctx, const std::vector<geometry::SpiralCell>& spirals, int start, bool cw,
                         double decomposition_angle) {
  Route route = spiralCellRoute(cctx, spirals.front(), start, cw, decomposition_angle);
  for (size_t k = 1; k < spirals.size() && route.points.size() >= 2; ++k) {
    const Ring& lap = spirals[k].laps.front();
    int nearest = 0;
    for (size_t v = 1; v < lap.size(); ++v)
      if ((lap[v] - route.points.back()).norm() < (lap[nearest] - route.points.back()).norm())
        nearest = static_cast<int>(v);
    const Route next = spiralCellRoute(cctx, spirals[k], nearest, cw, decomposition_angle);
    if (next.points.size() < 2) continue;
    appendVia(cctx, route, next);
  }
  return route;
}

// Adds to `out` the spiral candidates of the cell of `cctx`: every start vertex both ways ranked
// by stopEstimate, the kMaxSpiralKeep best scored exactly and kept within kKeepWithin of the
// cheapest candidate already in `out`.
void addSpiralCandidates(const Context& cctx, double decomposition_angle, RouteScorer& scorer, const StopTable& stop,
                         int* count, std::vector<CellCandidate>& out) {
  std::vector<geometry::SpiralCell> spirals;
  try {
    spirals = geometry::decomposeSpiral(cctx.problem->area, cctx.problem->spacing, decomposition_angle);
  } catch (const std::exception&) {
    spirals.clear();  // no spiral for this cell; its boustrophedon candidates remain
  }
  spirals.erase(std::remove_if(spirals.begin(), spirals.end(),
                               [](const geometry::SpiralCell& c) { return c.laps.empty() || c.laps.front().empty(); }),
                spirals.end());
  if (spirals.empty()) return;
  std::vector<std::pair<double, CellCandidate>> ranked;
  for (int start : spiralStarts(spirals.front()))
    for (bool cw : {false, true}) {
      CellCandidate c;
      c.spiral = true;
      c.route = chainedSpiralRoute(cctx, spirals, start, cw, decomposition_angle);
      ++*count;
      if (c.route.points.size() < 2) continue;
      const double e = stopEstimate(c.route, stop, scorer);
      ranked.emplace_back(e, std::move(c));
    }
  std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (ranked.size() > kMaxSpiralKeep) ranked.resize(kMaxSpiralKeep);
  double best_cost = kInf;
  for (const auto& c : out) best_cost = std::min(best_cost, c.cost);
  for (auto& [e, c] : ranked) {
    c.cost = scorer.energy(c.route);
    ++*count;
    if (std::isfinite(c.cost) && c.cost <= kKeepWithin * best_cost) out.push_back(std::move(c));
  }
}

// Candidates of one boustrophedon cell (ring `boundary`, no holes inside): boustrophedon at every
// coarse angle, refined around the cell's best (ranked by stopEstimate), then scored exactly with
// each start corner at the best angle and at the decomposition's angle; and the straight-skeleton
// spiral from every start vertex both ways (ranked by stopEstimate, the kMaxSpiralKeep best scored
// exactly). `count` counts the routes scored.
std::vector<CellCandidate> cellCandidates(const Context& ctx, const Ring& boundary, double decomposition_angle,
                                          const PlannerSettings& ps, RouteScorer& scorer, const StopTable& stop,
                                          int* count) {
  SurveyProblem cell_problem = *ctx.problem;
  cell_problem.area = geometry::PolygonWithHoles{boundary, {}};
  Context cctx = ctx;
  cctx.problem = &cell_problem;
  std::vector<CellCandidate> out = boustrophedonCandidates(cctx, decomposition_angle, ps, scorer, stop, count);
  if (ps.spirals) addSpiralCandidates(cctx, decomposition_angle, scorer, stop, count, out);
  return out;
}

// The distinct pieces of both partitions and the piece indices of (a) the cells and (b) the cells
// cut into convex pieces.
struct Pieces {
  std::vector<Ring> rings;
  std::vector<std::vector<int>> partitions = std::vector<std::vector<int>>(2);
};

Pieces piecesOf(const geometry::BoustrophedonDecomposition& dec) {
  Pieces out;
  for (const auto& cell : dec.cells) {
    const int id = static_cast<int>(out.rings.size());
    out.rings.push_back(cell.boundary);
    out.partitions[0].push_back(id);
    std::vector<Ring> parts;
    try {
      parts = geometry::convexPartition(cell.boundary);
    } catch (const std::exception&) {
      parts.clear();  // not partitioned: the cell stays whole in (b)
    }
    if (parts.size() <= 1 || parts.size() > kMaxConvexPieces) {
      // Convex already, or an outline of many small bends (a wavy field edge): pieces that small
      // only add transits and turns, so the cell stays whole.
      out.partitions[1].push_back(id);
      continue;
    }
    for (auto& part : parts) {
      out.partitions[1].push_back(static_cast<int>(out.rings.size()));
      out.rings.push_back(std::move(part));
    }
  }
  return out;
}

// cellCandidates() of every piece, spread over ps.threads workers (each with its own scorer).
std::vector<std::vector<CellCandidate>> candidatesPerPiece(const Context& ctx, const std::vector<Ring>& pieces,
                                                           double angle, const energy::EnergyModel& model,
                                                           const SpeedSettings& ss, const PlannerSettings& ps,
                                                           const StopTable& stop, int* count) {
  const size_t n = pieces.size();
  std::vector<std::vector<CellCandidate>> per(n);
  std::vector<int> counts(n, 0);
  const int nt = std::max(1, std::min<int>(ps.threads, static_cast<int>(n)));
  onWorkers(nt, [&](int t) {
    RouteScorer local(model, ss);
    for (size_t i = t; i < n; i += nt) per[i] = cellCandidates(ctx, pieces[i], angle, ps, local, stop, &counts[i]);
  });
  for (int c : counts) *count += c;
  return per;
}

// The plan of one partition (`partition`: piece indices): one GTSP picks a candidate per piece and
// the order; `info` receives what was chosen per visited piece. nullopt when no piece has a candidate.
std::optional<AngleResult> partitionPlan(const Context& ctx, const Pieces& pieces, const std::vector<int>& partition,
                                         const std::vector<std::vector<CellCandidate>>& per, double angle,
                                         RouteScorer& scorer, const StopTable& stop, const PlannerSettings& ps,
                                         std::vector<CellPlan>* info) {
  std::vector<Route> cand;
  std::vector<const CellCandidate*> meta;
  std::vector<int> piece_of;
  GtspInstance g;
  int cluster = 0;
  for (int id : partition) {
    if (per[static_cast<size_t>(id)].empty()) continue;  // a sliver with no sweep line
    for (const auto& c : per[static_cast<size_t>(id)]) {
      cand.push_back(c.route);
      meta.push_back(&c);
      piece_of.push_back(id);
      g.cluster.push_back(cluster);
      g.cost.push_back(c.cost);
    }
    ++cluster;
  }
  if (cand.empty()) return std::nullopt;
  AngleResult res;
  res.angle = angle;
  res.cells = cluster;
  res = assemble(ctx, std::move(cand), std::move(g), res, scorer, stop, Objective::Energy, ps.exact_max_cells,
                 cluster <= ps.exact_max_cells);
  for (int k : res.chosen) {
    const CellCandidate& c = *meta[static_cast<size_t>(k)];
    const Ring& piece = pieces.rings[static_cast<size_t>(piece_of[static_cast<size_t>(k)])];
    info->push_back({c.spiral ? "spiral" : "boustrophedon", c.spiral ? 0.0 : normDeg(c.angle), c.cost,
                     std::abs(geometry::signedArea(piece))});
  }
  return res;
}

// Per-cell search on two partitions of the area: (a) geometry's boustrophedon cells at `angle`
// [rad] (holes and inner no-fly zones cut them), (b) those cells cut further into convex pieces
// (geometry::convexPartition), so that e.g. the two arms of an L can take different sweep angles.
// Every distinct piece offers boustrophedon routes at its own best angle and spirals (pieces
// spread over `ps.threads` workers); per partition one GTSP picks a candidate per piece and the
// order; the cheaper partition is returned. `count` is increased by the routes scored; `info`
// receives, per visited piece in flight order, what was chosen; nullopt with `why` set when the
// search cannot run.
std::optional<AngleResult> perCellPlan(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                                       RouteScorer& scorer, const StopTable& stop, const PlannerSettings& ps,
                                       double angle, int* count, std::vector<CellPlan>* info, std::string* why) {
  const auto area = areaWithZones(*ctx.problem, why);
  if (!area) return std::nullopt;
  geometry::BoustrophedonDecomposition dec;
  try {
    dec = geometry::decomposeBoustrophedon(*area, angle);
  } catch (const std::exception& e) {
    *why = e.what();
    return std::nullopt;
  }
  if (dec.cells.empty()) {
    *why = "the decomposition has no cells";
    return std::nullopt;
  }
  const Pieces pieces = piecesOf(dec);
  const auto per = candidatesPerPiece(ctx, pieces.rings, angle, model, ss, ps, stop, count);
  std::optional<AngleResult> best;
  for (size_t v = 0; v < pieces.partitions.size(); ++v) {
    if (v == 1 && pieces.partitions[1] == pieces.partitions[0]) break;  // every cell already convex
    std::vector<CellPlan> chosen;
    auto res = partitionPlan(ctx, pieces, pieces.partitions[v], per, angle, scorer, stop, ps, &chosen);
    if (!res || (best && best->score <= res->score)) continue;
    *info = std::move(chosen);
    best = std::move(res);
  }
  if (!best) *why = "no cell has a candidate route";
  return best;
}

}  // namespace

std::optional<PlanCandidate> perCellCandidate(const Context& ctx, const energy::EnergyModel& model,
                                              const SpeedSettings& ss, RouteScorer& scorer, const StopTable& stop,
                                              const PlannerSettings& ps,
                                              const std::vector<geometry::PolygonWithHoles>& free, double angle,
                                              int* count, std::string* why) {
  std::vector<CellPlan> info;
  const auto mixed = perCellPlan(ctx, model, ss, scorer, stop, ps, angle, count, &info, why);
  if (!mixed) return std::nullopt;
  const bool all_spiral = std::all_of(info.begin(), info.end(), [](const CellPlan& c) { return c.pattern == "spiral"; });
  const bool any_spiral = std::any_of(info.begin(), info.end(), [](const CellPlan& c) { return c.pattern == "spiral"; });
  const char* pattern = all_spiral ? "spiral" : any_spiral ? "mixed" : "boustrophedon";
  PlanCandidate c = finish(free, ctx.problem->footprint, scorer, *mixed, pattern);
  // The reported angle: the largest boustrophedon cell's.
  double largest = -1.0;
  for (const auto& cp : info)
    if (cp.pattern == "boustrophedon" && cp.area_m2 > largest) {
      largest = cp.area_m2;
      c.sweep_angle_deg = cp.sweep_angle_deg;
    }
  if (all_spiral) c.sweep_angle_deg = 0.0;
  c.cell_plans = std::move(info);
  return c;
}

}  // namespace wattswath::planner::detail
