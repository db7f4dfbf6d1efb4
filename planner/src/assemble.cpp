// Joining per-cell candidates into one flight: each candidate also offered reversed, transit
// costs between distinct end points, the GTSP order (planner/order.cpp), and the route from home
// through the chosen candidates back home with transits around obstacles.
#include "assemble.hpp"

#include <utility>

namespace wattswath::planner::detail {
namespace {

using geometry::LegRole;
using geometry::Point;

// Each candidate reversed is also a candidate (same internal cost, swapped ends), unless a
// candidate of the cell already runs between the same two ends (the reverse of a zigzag from one
// corner is usually the zigzag from its end corner): the order search then has half the nodes.
// Returns the input candidate each candidate came from.
std::vector<int> addReversed(std::vector<Route>& cand, GtspInstance& g) {
  const size_t base = cand.size();
  std::vector<int> origin(base);
  for (size_t i = 0; i < base; ++i) origin[i] = static_cast<int>(i);
  for (size_t i = 0; i < base; ++i) {
    const Point& from = cand[i].points.back();
    const Point& to = cand[i].points.front();
    bool same_ends = false;
    for (size_t k = 0; k < base && !same_ends; ++k)
      same_ends = g.cluster[k] == g.cluster[i] && cand[k].points.front() == from && cand[k].points.back() == to &&
                  g.cost[k] <= g.cost[i];
    if (same_ends) continue;
    cand.push_back(reversed(cand[i]));
    origin.push_back(static_cast<int>(i));
    g.cluster.push_back(g.cluster[i]);
    g.cost.push_back(g.cost[i]);
  }
  return origin;
}

// The distinct end points (home first) and, per candidate, the index of its entry and exit among
// them (index n, the depot, is home: end 0). A candidate and its reverse share both ends, and the
// start corners of a cell share theirs, so transits are computed once per pair of distinct ends.
struct Ends {
  std::vector<Point> points;
  std::vector<int> entry, exit;
};

Ends endsOf(const Context& ctx, const std::vector<Route>& cand) {
  const int n = static_cast<int>(cand.size());
  Ends e;
  e.points.push_back(ctx.problem->home);
  auto indexOf = [&e](const Point& p) {
    for (size_t k = 0; k < e.points.size(); ++k)
      if (e.points[k] == p) return static_cast<int>(k);
    e.points.push_back(p);
    return static_cast<int>(e.points.size()) - 1;
  };
  e.entry.assign(n + 1, 0);
  e.exit.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    e.entry[i] = indexOf(cand[i].points.front());
    e.exit[i] = indexOf(cand[i].points.back());
  }
  return e;
}

// The route from home through the candidates of `tour` back home; `chosen` receives the input
// candidate of each visited node.
Route joinTour(const Context& ctx, const std::vector<Route>& cand, const std::vector<int>& origin, const GtspTour& tour,
               std::vector<int>* chosen) {
  Route full;
  full.points.push_back(ctx.problem->home);
  full.max_tangent.push_back(0.0);
  for (int node : tour.nodes) {
    chosen->push_back(origin[static_cast<size_t>(node)]);
    appendVia(ctx, full, cand[node]);
  }
  moveTo(ctx, full, ctx.problem->home, LegRole::Transit, 0.0);
  return full;
}

}  // namespace

AngleResult assemble(const Context& ctx, std::vector<Route> cand, GtspInstance g, AngleResult res, RouteScorer& scorer,
                     const StopTable& stop, Objective obj, int exact_max_cells, bool also_length_order) {
  const std::vector<int> origin = addReversed(cand, g);
  const int n = static_cast<int>(cand.size());
  const Ends ends = endsOf(ctx, cand);
  const int m = static_cast<int>(ends.points.size());
  const auto routes = ctx.router->routeAll(ends.points);
  // The order search works on estimates (candidates flown alone from rest to rest, transits
  // stop to stop), so for the energy objective the order that is shortest is also built and the
  // one whose joined route really costs less energy is kept.
  std::vector<Objective> orders{obj};
  if (obj == Objective::Energy && also_length_order) orders.push_back(Objective::Length);
  for (Objective order : orders) {
    Eigen::MatrixXd between = Eigen::MatrixXd::Zero(m, m);
    for (int p = 0; p < m; ++p)
      for (int q = p + 1; q < m; ++q)
        between(p, q) = between(q, p) = polylineCost(routes[static_cast<size_t>(p) * m + q], order, stop, scorer);
    GtspInstance go = g;
    if (order != obj)
      for (int i = 0; i < n; ++i) go.cost[static_cast<size_t>(i)] = cand[static_cast<size_t>(i)].length();
    go.transit = Eigen::MatrixXd::Zero(n + 1, n + 1);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        if (i != j || i == n) go.transit(i, j) = between(ends.exit[i], ends.entry[j]);
    std::vector<int> chosen;
    Route full = joinTour(ctx, cand, origin, solveGtsp(go, exact_max_cells), &chosen);
    const double score = obj == Objective::Length ? full.length() : scorer.energy(full);
    if (score < res.score) {
      res.score = score;
      res.route = std::move(full);
      res.chosen = std::move(chosen);
    }
  }
  return res;
}

}  // namespace wattswath::planner::detail
