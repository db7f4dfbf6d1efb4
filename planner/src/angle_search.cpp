// The one-angle search: boustrophedon routes over the whole area at each sweep angle of a coarse
// grid, refined around the best; the few best angles flown in full and checked for coverage.
#include "angle_search.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "assemble.hpp"
#include "verification.hpp"

namespace wattswath::planner::detail {
namespace {

constexpr size_t kFinishBest = 8;  // best-ranked angles flown in full before choosing
constexpr size_t kMaxBatches = 4;  // batches of kFinishBest flown at most while none keeps coverage
constexpr size_t kEdgeAngles = 4;  // directions of the longest outline edges added to the coarse angles
// One line fewer than full coverage needs is tried at an angle when those lines' band still spans
// this share of the area's extent across the lines (below it the coverage check would refuse it).
constexpr double kFewerLinesBand = 0.985;

// Whether one sweep line fewer at `angle` [rad] may still keep coverage: (n - 1) spacings of
// band over the extent H across the lines, n = ceil(H / spacing) the full-coverage count.
bool fewerLinesWorthTrying(const Context& ctx, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  double lo = kInf, hi = -kInf;
  for (const auto& p : ctx.problem->area.outer) {
    const double y = -s * p.x() + c * p.y();
    lo = std::min(lo, y);
    hi = std::max(hi, y);
  }
  const double d = ctx.problem->spacing, h = hi - lo;
  const int full = static_cast<int>(std::ceil(h / d - 1e-9));
  return full >= 2 && (full - 1) * d >= kFewerLinesBand * h;
}

// Evaluates `angles` on `threads` workers, each with its own scorer.
std::vector<AngleResult> evaluateAngles(const Context& ctx, const std::vector<double>& angles,
                                        const energy::EnergyModel& model, const SpeedSettings& ss,
                                        const StopTable& stop, Objective obj, int threads, int exact_max_cells) {
  std::vector<AngleResult> out(angles.size());
  const int nt = std::max(1, std::min<int>(threads, static_cast<int>(angles.size())));
  onWorkers(nt, [&](int t) {
    // The scan ranks angles of boustrophedon routes, whose corners are far apart: arcs at chain
    // speeds change little there, and scoring without them is several times faster.
    SpeedSettings scan = ss;
    scan.arc_chains = false;
    RouteScorer scorer(model, scan);
    for (size_t i = t; i < angles.size(); i += nt)
      out[i] = evaluateAngle(ctx, angles[i], scorer, stop, obj, exact_max_cells);
  });
  return out;
}

}  // namespace

AngleResult evaluateAngle(const Context& ctx, double angle, RouteScorer& scorer, const StopTable& stop, Objective obj,
                          int exact_max_cells, bool also_length_order) {
  AngleResult res;
  res.angle = angle;
  double first_y = 0.0;
  const auto cells = sweepCells(ctx, angle, &first_y);
  if (cells.empty()) return res;
  std::vector<Route> cand;
  GtspInstance g;
  int cluster = 0;
  for (size_t ci = 0; ci < cells.size(); ++ci) {
    bool any = false;
    for (int top = 0; top < 2; ++top) {
      for (bool right : {false, true}) {
        const Route r = cellRoute(ctx, cells[ci], angle, first_y, top == 1, right);
        if (r.points.size() < 2) continue;  // a sliver without length
        const double cost = obj == Objective::Length ? r.length() : scorer.energy(r);
        if (!std::isfinite(cost)) continue;
        cand.push_back(r);
        g.cluster.push_back(cluster);
        g.cost.push_back(cost);
        any = true;
      }
    }
    cluster += any;
  }
  if (cand.empty()) return res;
  res.cells = cluster;
  return assemble(ctx, std::move(cand), std::move(g), res, scorer, stop, obj, exact_max_cells, also_length_order);
}

std::vector<AngleResult> searchAngles(const Context& ctx, const energy::EnergyModel& model, const SpeedSettings& ss,
                                      const StopTable& stop, Objective obj, const PlannerSettings& ps, int* count,
                                      std::vector<AngleScore>* scan) {
  std::vector<double> coarse;
  for (double a = 0.0; a < 180.0 - 1e-9; a += ps.coarse_step_deg) coarse.push_back(a * kDeg);
  // The directions of the four longest outline edges (at least two spacings long) too: lines
  // along an edge end nowhere on it, while lines a degree off it cross it and, ending on the
  // boundary since issue 22, leave a long thin wedge beside it uncovered.
  const auto& outer = ctx.problem->area.outer;
  std::vector<geometry::Point> edges;
  for (size_t i = 0; i < outer.size(); ++i) edges.push_back(outer[(i + 1) % outer.size()] - outer[i]);
  std::sort(edges.begin(), edges.end(), [](const auto& u, const auto& v) { return u.norm() > v.norm(); });
  for (size_t i = 0; i < std::min(edges.size(), kEdgeAngles); ++i) {
    const geometry::Point& e = edges[i];
    if (e.norm() < 2.0 * ctx.problem->spacing) break;
    const double a = normDeg(std::atan2(e.y(), e.x())) * kDeg;
    const bool known = std::any_of(coarse.begin(), coarse.end(), [&](double c) { return std::abs(c - a) < 1e-6; });
    if (!known) coarse.push_back(a);
  }
  auto res = evaluateAngles(ctx, coarse, model, ss, stop, obj, ps.threads, ps.exact_max_cells);
  *count += static_cast<int>(res.size());
  std::sort(res.begin(), res.end(), [](const auto& a, const auto& b) { return a.score < b.score; });
  std::vector<double> fine;
  for (size_t k = 0; k < std::min<size_t>(2, res.size()); ++k) {
    if (!std::isfinite(res[k].score)) continue;
    for (double da = -ps.coarse_step_deg + ps.fine_step_deg; da < ps.coarse_step_deg - 1e-9; da += ps.fine_step_deg)
      if (std::abs(da) > 1e-9) fine.push_back(res[k].angle + da * kDeg);
  }
  auto more = evaluateAngles(ctx, fine, model, ss, stop, obj, ps.threads, ps.exact_max_cells);
  *count += static_cast<int>(more.size());
  if (scan) {
    for (const auto* list : {&res, &more})
      for (const auto& r : *list) scan->push_back({normDeg(r.angle), r.score});
    std::sort(scan->begin(), scan->end(), [](const auto& a, const auto& b) { return a.sweep_angle_deg < b.sweep_angle_deg; });
  }
  for (auto& r : more) res.push_back(std::move(r));
  std::stable_sort(res.begin(), res.end(), [](const auto& a, const auto& b) { return a.score < b.score; });
  return res;
}

// bestAnglePlan over the batch of up to kFinishBest ranked angles from `first` on.
static PlanCandidate bestOfBatch(const Context& ctx, const std::vector<AngleResult>& ranked, size_t first,
                                 const energy::EnergyModel& model, const SpeedSettings& ss, RouteScorer& scorer,
                                 const StopTable& stop, const PlannerSettings& ps,
                                 const std::vector<geometry::PolygonWithHoles>& free, LineCountNeighbour* neighbour) {
  // The search ranks angles by the order search's estimate; the few best are flown in full (with
  // the coverage check, which may take arcs back) and the cheapest that keeps coverage is kept.
  // Re-assembled with the shortest order as a second choice (see assemble()), on ps.threads workers.
  // Each finalist also with one sweep line fewer (where its band may still keep coverage): the
  // last fraction of a per cent of coverage can cost a whole line (issue 22); the coverage check
  // below keeps it only when coverage stays >= kMinCoveragePct.
  size_t finals = 0;
  while (first + finals < ranked.size() && finals < kFinishBest && std::isfinite(ranked[first + finals].score)) ++finals;
  Context fewer = ctx;
  fewer.fewer_lines = 1;
  std::vector<PlanCandidate> finished(2 * finals);
  std::vector<AngleResult> flown_from(2 * finals);
  const int nt = std::max(1, std::min<int>(ps.threads, static_cast<int>(finals)));
  onWorkers(nt, [&](int t) {
    RouteScorer local(model, ss);
    for (size_t k = t; k < finals; k += nt) {
      const AngleResult both =
          evaluateAngle(ctx, ranked[first + k].angle, local, stop, Objective::Energy, ps.exact_max_cells, true);
      flown_from[k] = both.score < ranked[first + k].score ? both : ranked[first + k];
      finished[k] = flyUnverified(local, flown_from[k], "boustrophedon");
      if (!fewerLinesWorthTrying(ctx, ranked[first + k].angle)) continue;
      flown_from[finals + k] =
          evaluateAngle(fewer, ranked[first + k].angle, local, stop, Objective::Energy, ps.exact_max_cells, true);
      finished[finals + k] = flyUnverified(local, flown_from[finals + k], "boustrophedon");
    }
  });
  // The exact coverage check (CGAL Booleans) costs as much as flying a route, so the finalists are
  // checked lazily, cheapest first: once one keeps coverage, a finalist whose widest-arc energy is
  // already higher cannot win (narrower arcs only take its energy up, not down).
  std::vector<size_t> by_energy(2 * finals);
  for (size_t k = 0; k < 2 * finals; ++k) by_energy[k] = k;
  std::sort(by_energy.begin(), by_energy.end(),
            [&](size_t a, size_t b) { return finished[a].flown.energy < finished[b].flown.energy; });
  size_t best = finished.size();
  for (size_t k : by_energy) {
    auto& c = finished[k];
    if (!c.valid) continue;
    const bool have = best < finished.size();
    if (have && finished[best].coverage_pct >= kMinCoveragePct && c.flown.energy >= finished[best].flown.energy) break;
    verify(free, ctx.problem->footprint, scorer, flown_from[k], c);
    if (!have || better(c, finished[best])) best = k;
  }
  if (best == finished.size()) return {};
  if (neighbour) {  // the same angle with one line more (the plan dropped one) or one fewer
    const size_t other = best >= finals ? best - finals : best + finals;
    if (finished[other].valid) {
      if (std::isnan(finished[other].coverage_pct)) verify(free, ctx.problem->footprint, scorer, flown_from[other], finished[other]);
      neighbour->candidate = finished[other];
      neighbour->lines_delta = best >= finals ? 1 : -1;
    }
  }
  return std::move(finished[best]);
}

PlanCandidate bestAnglePlan(const Context& ctx, const std::vector<AngleResult>& ranked, const energy::EnergyModel& model,
                            const SpeedSettings& ss, RouteScorer& scorer, const StopTable& stop,
                            const PlannerSettings& ps, const std::vector<geometry::PolygonWithHoles>& free,
                            LineCountNeighbour* neighbour) {
  // Lines end on the boundary (issue 22), so the cheapest angles can be the ones that cut an
  // edge's corners and miss coverage: when no angle of a batch keeps it, the next batch is flown.
  PlanCandidate plan;
  for (size_t first = 0; first < std::min(ranked.size(), kMaxBatches * kFinishBest); first += kFinishBest) {
    LineCountNeighbour local;
    PlanCandidate c = bestOfBatch(ctx, ranked, first, model, ss, scorer, stop, ps, free, &local);
    if (!better(c, plan)) continue;
    plan = std::move(c);
    if (neighbour) *neighbour = local;
    if (plan.coverage_pct >= kMinCoveragePct) break;
  }
  return plan;
}

}  // namespace wattswath::planner::detail
