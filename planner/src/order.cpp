#include "wattswath/planner/order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dag_shortest_paths.hpp>


namespace wattswath::planner {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kImproveRel = 1e-12;  // [-] relative improvement a local-search move must make
constexpr int kDpMovesMaxClusters = 16;  // moves scored with re-chosen candidates up to this many clusters
constexpr double kSkipMargin = 1e-9;     // [-] relative rounding allowance of a move's O(1) estimate


std::vector<std::vector<int>> membersOf(const GtspInstance& g) {
  std::vector<std::vector<int>> m(g.clusterCount());
  for (size_t i = 0; i < g.cluster.size(); ++i) m[g.cluster[i]].push_back(static_cast<int>(i));
  return m;
}

// Best candidate per cluster for a fixed cluster order: shortest path through the layered graph
// depot -> layer 1 -> ... -> layer k -> depot (dynamic programming over the layers).
// Cost only of bestForOrder (no allocation once the buffers have grown): the local search calls
// this for every move and rebuilds the tour only for an accepted one.
double orderCost(const GtspInstance& g, const std::vector<std::vector<int>>& members, const std::vector<int>& order,
                 std::vector<double>& cur, std::vector<double>& next) {
  if (order.empty()) return kInf;
  const int n = static_cast<int>(g.cluster.size());
  const auto& first = members[order[0]];
  cur.resize(first.size());
  for (size_t b = 0; b < first.size(); ++b) cur[b] = g.transit(n, first[b]) + g.cost[first[b]];
  for (size_t l = 1; l < order.size(); ++l) {
    const auto& prev = members[order[l - 1]];
    const auto& now = members[order[l]];
    next.assign(now.size(), kInf);
    for (size_t b = 0; b < now.size(); ++b) {
      double best = kInf;
      for (size_t a = 0; a < prev.size(); ++a) best = std::min(best, cur[a] + g.transit(prev[a], now[b]));
      next[b] = best + g.cost[now[b]];
    }
    cur.swap(next);
  }
  const auto& last = members[order.back()];
  double c = kInf;
  for (size_t b = 0; b < last.size(); ++b) c = std::min(c, cur[b] + g.transit(last[b], n));
  return c;
}

// The graph of cells and their candidates for a fixed cluster order, as a Boost.Graph DAG: vertex
// 0 is the depot leaving, then every candidate of layer 1, 2, ..., k (a candidate is a way through
// its cell: entry point, exit point, internal cost), then the depot returning. An edge from a
// candidate to one of the next layer weighs the transit between them plus the next candidate's
// internal cost; the best candidates are the shortest depot-to-depot path (dag_shortest_paths).
// orderCost() computes the same cost without building the graph, for the local search's moves.
GtspTour bestForOrder(const GtspInstance& g, const std::vector<std::vector<int>>& members,
                      const std::vector<int>& order) {
  GtspTour t;
  t.cost = kInf;
  if (order.empty()) return t;
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, boost::no_property,
                                      boost::property<boost::edge_weight_t, double>>;
  const int n = static_cast<int>(g.cluster.size());
  std::vector<int> first_vertex(order.size() + 1);  // graph vertex of each layer's first candidate
  int vertices = 1;
  for (size_t l = 0; l < order.size(); ++l) {
    first_vertex[l] = vertices;
    vertices += static_cast<int>(members[order[l]].size());
  }
  first_vertex[order.size()] = vertices;  // the returning depot
  Graph dag(static_cast<size_t>(vertices) + 1);
  const auto& first = members[order[0]];
  for (size_t b = 0; b < first.size(); ++b)
    boost::add_edge(0, first_vertex[0] + static_cast<int>(b), g.transit(n, first[b]) + g.cost[first[b]], dag);
  for (size_t l = 1; l < order.size(); ++l) {
    const auto& prev = members[order[l - 1]];
    const auto& now = members[order[l]];
    for (size_t a = 0; a < prev.size(); ++a)
      for (size_t b = 0; b < now.size(); ++b)
        boost::add_edge(first_vertex[l - 1] + static_cast<int>(a), first_vertex[l] + static_cast<int>(b),
                        g.transit(prev[a], now[b]) + g.cost[now[b]], dag);
  }
  const auto& last = members[order.back()];
  for (size_t b = 0; b < last.size(); ++b)
    boost::add_edge(first_vertex[order.size() - 1] + static_cast<int>(b), vertices, g.transit(last[b], n), dag);
  std::vector<double> dist(static_cast<size_t>(vertices) + 1, kInf);
  std::vector<std::size_t> pred(static_cast<size_t>(vertices) + 1);
  boost::dag_shortest_paths(dag, 0, boost::distance_map(dist.data()).predecessor_map(pred.data()));
  t.cost = dist[static_cast<size_t>(vertices)];
  if (!std::isfinite(t.cost)) return t;
  t.nodes.resize(order.size());
  std::size_t v = pred[static_cast<size_t>(vertices)];
  for (size_t l = order.size(); l-- > 0;) {
    t.nodes[l] = members[order[l]][v - static_cast<std::size_t>(first_vertex[l])];
    v = pred[v];
  }
  return t;
}

// O(1) estimates of the local-search moves' costs for an order whose candidates are fixed (`sel`):
// prefix sums of the transits along the order, forwards and backwards, give a reversed run's
// transits without walking it. The search uses them only to skip moves that cannot pass its
// acceptance test; a move that might is scored exactly, as before, so the tour found is the same.
struct FixedOrderEstimate {
  const GtspInstance& g;
  const std::vector<int>& sel;  // cluster -> chosen candidate
  std::vector<double> fwd, bwd;  // [t]: transits node(0)..node(t) forwards / reversed
  std::vector<int> node;         // candidate at each position of the order

  void update(const std::vector<int>& order) {
    const size_t k = order.size();
    node.resize(k);
    fwd.assign(k, 0.0);
    bwd.assign(k, 0.0);
    for (size_t t = 0; t < k; ++t) node[t] = sel[static_cast<size_t>(order[t])];
    for (size_t t = 1; t < k; ++t) {
      fwd[t] = fwd[t - 1] + g.transit(node[t - 1], node[t]);
      bwd[t] = bwd[t - 1] + g.transit(node[t], node[t - 1]);
    }
  }
  int depot() const { return static_cast<int>(g.cluster.size()); }
  int at(int t) const { return t < 0 || t >= static_cast<int>(node.size()) ? depot() : node[static_cast<size_t>(t)]; }
  /// Change of the tour's cost when positions i..j are reversed.
  double reverse(int i, int j) const {
    const double before = g.transit(at(i - 1), at(i)) + (fwd[j] - fwd[i]) + g.transit(at(j), at(j + 1));
    const double after = g.transit(at(i - 1), at(j)) + (bwd[j] - bwd[i]) + g.transit(at(i), at(j + 1));
    return after - before;
  }
  /// Change when the run i..i+len-1 moves to index j of the order without it (j != i).
  double move(int i, int len, int j) const {
    const int a = at(i), b = at(i + len - 1), p = at(i - 1), q = at(i + len);
    auto rest = [&](int m) { return m < 0 || m >= static_cast<int>(node.size()) - len ? depot() : at(m < i ? m : m + len); };
    const int x = rest(j - 1), y = rest(j);
    return g.transit(p, q) - g.transit(p, a) - g.transit(b, q) + g.transit(x, a) + g.transit(b, y) - g.transit(x, y);
  }
};

}  // namespace

int GtspInstance::clusterCount() const {
  int k = 0;
  for (int c : cluster) k = std::max(k, c + 1);
  return k;
}

void GtspInstance::validate() const {
  const auto n = static_cast<Eigen::Index>(cluster.size());
  if (cost.size() != cluster.size())
    throw std::invalid_argument("GtspInstance: cost has " + std::to_string(cost.size()) + " entries, cluster " +
                                std::to_string(cluster.size()));
  if (transit.rows() != n + 1 || transit.cols() != n + 1)
    throw std::invalid_argument("GtspInstance: transit is " + std::to_string(transit.rows()) + "x" +
                                std::to_string(transit.cols()) + ", expected " + std::to_string(n + 1) +
                                " square (candidates + depot)");
  std::vector<int> count(clusterCount(), 0);
  for (size_t i = 0; i < cluster.size(); ++i) {
    if (cluster[i] < 0) throw std::invalid_argument("GtspInstance: cluster[" + std::to_string(i) + "] is negative");
    if (!std::isfinite(cost[i]) || cost[i] < 0.0)
      throw std::invalid_argument("GtspInstance: cost[" + std::to_string(i) + "] = " + std::to_string(cost[i]) +
                                  " must be finite and >= 0");
    ++count[cluster[i]];
  }
  for (size_t c = 0; c < count.size(); ++c)
    if (count[c] == 0) throw std::invalid_argument("GtspInstance: cluster " + std::to_string(c) + " has no candidate");
  if (!transit.allFinite() || (transit.array() < 0.0).any())
    throw std::invalid_argument("GtspInstance: transit costs must be finite and >= 0");
}

double tourCost(const GtspInstance& g, const std::vector<int>& nodes) {
  const int depot = static_cast<int>(g.cluster.size());
  double c = 0.0;
  int prev = depot;
  for (int v : nodes) {
    c += g.transit(prev, v) + g.cost[v];
    prev = v;
  }
  return c + g.transit(prev, depot);
}

GtspTour solveGtspExact(const GtspInstance& g) {
  g.validate();
  const int k = g.clusterCount();
  if (k > kGtspExactMaxClusters)
    throw std::invalid_argument("solveGtspExact: " + std::to_string(k) + " clusters, at most " +
                                std::to_string(kGtspExactMaxClusters) + " supported");
  if (k == 0) return {};
  const int n = static_cast<int>(g.cluster.size());
  const size_t full = (size_t{1} << k) - 1;
  // best[mask][node]: cheapest path from the depot visiting exactly the clusters in mask, ending at node.
  std::vector<std::vector<double>> best(full + 1, std::vector<double>(n, kInf));
  std::vector<std::vector<int>> from(full + 1, std::vector<int>(n, -1));
  for (int v = 0; v < n; ++v) best[size_t{1} << g.cluster[v]][v] = g.transit(n, v) + g.cost[v];
  for (size_t mask = 1; mask <= full; ++mask) {
    for (int u = 0; u < n; ++u) {
      const double bu = best[mask][u];
      if (!(bu < kInf)) continue;
      for (int v = 0; v < n; ++v) {
        const size_t bit = size_t{1} << g.cluster[v];
        if (mask & bit) continue;
        const double c = bu + g.transit(u, v) + g.cost[v];
        if (c < best[mask | bit][v]) {
          best[mask | bit][v] = c;
          from[mask | bit][v] = u;
        }
      }
    }
  }
  GtspTour t;
  t.cost = kInf;
  int last = -1;
  for (int v = 0; v < n; ++v) {
    const double c = best[full][v] + g.transit(v, n);
    if (c < t.cost) {
      t.cost = c;
      last = v;
    }
  }
  size_t mask = full;
  for (int v = last; v >= 0;) {
    t.nodes.push_back(v);
    const int u = from[mask][v];
    mask &= ~(size_t{1} << g.cluster[v]);
    v = u;
  }
  std::reverse(t.nodes.begin(), t.nodes.end());
  return t;
}

namespace {

// Greedy cluster order: from the depot, repeatedly to the cheapest (transit + internal) candidate of
// an unvisited cluster.
std::vector<int> greedyOrder(const GtspInstance& g) {
  const int k = g.clusterCount(), n = static_cast<int>(g.cluster.size());
  std::vector<int> order;
  std::vector<bool> done(k, false);
  int at = n;
  for (int step = 0; step < k; ++step) {
    double bc = kInf;
    int bv = -1;
    for (int v = 0; v < n; ++v) {
      if (done[g.cluster[v]]) continue;
      const double c = g.transit(at, v) + g.cost[v];
      if (c < bc) {
        bc = c;
        bv = v;
      }
    }
    done[g.cluster[bv]] = true;
    order.push_back(g.cluster[bv]);
    at = bv;
  }
  return order;
}

// Local search over a cluster order: 2-opt and or-opt moves, scored with each cluster's candidate
// fixed (`sel`) or with the candidates re-chosen for each order.
class OrderSearch {
 public:
  OrderSearch(const GtspInstance& g, std::vector<int> order)
      : g_(g), members_(membersOf(g)), order_(std::move(order)), sel_(static_cast<size_t>(g.clusterCount()), -1),
        est_{g, sel_, {}, {}, {}} {}

  // Re-chooses the candidates optimally for the order (layered DP); returns the tour's cost.
  double reselect() {
    const GtspTour t = bestForOrder(g_, members_, order_);
    for (size_t l = 0; l < order_.size(); ++l) sel_[static_cast<size_t>(order_[l])] = t.nodes[l];
    return t.cost;
  }
  // Moves scored with the candidates fixed, to a local optimum.
  void improveFixed() {
    search([&](const std::vector<int>& ord) { return fixedCost(ord); }, true, true);
  }
  // One pass of moves each scored with its own optimal candidates; true when one improved.
  bool improveOnce() {
    return search([&](const std::vector<int>& ord) { return orderCost(g_, members_, ord, buf_a_, buf_b_); }, false, false);
  }
  // The best tour of the order reached.
  GtspTour tour() const { return bestForOrder(g_, members_, order_); }

 private:
  // The cost of `ord` with each cluster's candidate fixed.
  double fixedCost(const std::vector<int>& ord) const {
    double c = 0.0;
    int prev = static_cast<int>(g_.cluster.size());
    for (int cl : ord) {
      const int v = sel_[static_cast<size_t>(cl)];
      c += g_.transit(prev, v) + g_.cost[v];
      prev = v;
    }
    return c + g_.transit(prev, static_cast<int>(g_.cluster.size()));
  }
  // Tries 2-opt and or-opt moves of the order scored by `score` (first improvement, restart);
  // `exhaust` repeats until no move improves, otherwise one improvement ends the call. With
  // `estimate` (fixed candidates) a move whose O(1) estimate cannot pass the acceptance test is
  // skipped unscored: its exact cost would differ from the estimate by rounding only (kSkipMargin).
  template <class Score>
  bool search(Score&& score, bool exhaust, bool estimate) {
    const int k = static_cast<int>(order_.size());
    double best_cost = score(order_);
    if (estimate) est_.update(order_);
    bool any = false, improved = true;
    auto hopeless = [&](double delta) {
      return estimate && best_cost + delta >= best_cost * (1.0 - kImproveRel) + kSkipMargin * (1.0 + std::abs(best_cost));
    };
    auto accept = [&]() {
      const double c = score(o_);
      if (c < best_cost * (1.0 - kImproveRel)) {
        order_ = o_;
        best_cost = c;
        if (estimate) est_.update(order_);
        return true;
      }
      return false;
    };
    while (improved) {
      improved = false;
      for (int i = 0; i < k && !improved; ++i) {
        for (int j = i + 1; j < k && !improved; ++j) {  // 2-opt: reverse order[i..j]
          if (hopeless(estimate ? est_.reverse(i, j) : 0.0)) continue;
          o_ = order_;
          std::reverse(o_.begin() + i, o_.begin() + j + 1);
          improved = accept();
        }
      }
      for (int len = 1; len <= 3 && !improved; ++len) {  // or-opt: move a run of 1..3 clusters
        for (int i = 0; i + len <= k && !improved; ++i) {
          for (int j = 0; j <= k - len && !improved; ++j) {
            if (j == i) continue;
            if (hopeless(estimate ? est_.move(i, len, j) : 0.0)) continue;
            rest_.assign(order_.begin(), order_.begin() + i);
            rest_.insert(rest_.end(), order_.begin() + i + len, order_.end());
            o_ = rest_;
            o_.insert(o_.begin() + std::min<int>(j, static_cast<int>(rest_.size())), order_.begin() + i,
                      order_.begin() + i + len);
            improved = accept();
          }
        }
      }
      any = any || improved;
      if (!exhaust) break;
    }
    return any;
  }

  const GtspInstance& g_;
  const std::vector<std::vector<int>> members_;
  std::vector<int> order_, o_, rest_;  // the order; scratch for the moves
  std::vector<int> sel_;               // cluster -> chosen candidate
  FixedOrderEstimate est_;
  std::vector<double> buf_a_, buf_b_;  // scratch for orderCost
};

}  // namespace

GtspTour solveGtspHeuristic(const GtspInstance& g) {
  g.validate();
  const int k = g.clusterCount();
  if (k == 0) return {};
  // Local search over the greedy cluster order, in two alternating phases: (1) moves scored with
  // each cluster's candidate fixed (O(k) per move), to a local optimum; then the candidates re-chosen
  // optimally for that order (layered DP), and (1) again while that helps; (2) up to
  // kDpMovesMaxClusters clusters, one pass of moves each scored with its own optimal candidates
  // (O(k m^2) per move): an improvement there goes back to (1), none ends the search.
  OrderSearch s(g, greedyOrder(g));
  double cost = s.reselect();
  for (;;) {
    s.improveFixed();
    const double c = s.reselect();
    const bool better = c < cost * (1.0 - kImproveRel);
    cost = std::min(cost, c);
    if (better) continue;  // new candidates may open new moves
    if (k > kDpMovesMaxClusters) break;
    if (!s.improveOnce()) break;
    cost = s.reselect();
  }
  return s.tour();
}

GtspTour solveGtsp(const GtspInstance& g, int exact_max_clusters) {
  if (g.clusterCount() <= std::min(exact_max_clusters, kGtspExactMaxClusters)) return solveGtspExact(g);
  return solveGtspHeuristic(g);
}

}  // namespace wattswath::planner
