#pragma once
/// @file order.hpp
/// Cell ordering as a generalised travelling salesman problem (GTSP): every cluster (a cell) has
/// candidates (ways to cover it: an entry point, an exit point and an internal cost); pick one
/// candidate per cluster and an order, from a depot (home) back to it, minimising the sum of
/// internal costs and transit costs. Exact dynamic programming over subsets for small instances
/// (a test oracle), a heuristic (greedy, 2-opt / or-opt over the order, optimal candidate choice
/// for a fixed order) beyond.

#include <vector>

#include <Eigen/Core>

namespace wattswath::planner {

/// A GTSP instance on nodes 0..n-1 (candidates) plus a depot with index n.
struct GtspInstance {
  std::vector<int> cluster;     ///< cluster index of each candidate node, in [0, clusterCount)
  std::vector<double> cost;     ///< [J] internal cost of each candidate
  Eigen::MatrixXd transit;      ///< [J] (n+1) x (n+1): from the exit of row to the entry of column; n = depot

  /// Number of clusters (1 + the largest cluster index; 0 when empty).
  int clusterCount() const;
  /// Throws std::invalid_argument naming the field when sizes or values are inconsistent
  /// (cluster without candidates, negative or non-finite cost, wrong matrix size).
  void validate() const;
};

/// A tour: candidate nodes in visiting order (one per cluster), depot implied at both ends.
struct GtspTour {
  std::vector<int> nodes;  ///< candidate node per visited cluster, in order
  double cost = 0.0;       ///< [J] total: internal costs plus transits, depot to depot
};

/// Total cost of visiting `nodes` in order from and back to the depot [J].
double tourCost(const GtspInstance& g, const std::vector<int>& nodes);

/// Largest number of clusters solveGtspExact accepts (2^k k-node states).
inline constexpr int kGtspExactMaxClusters = 12;

/// Exact optimum by dynamic programming over subsets of clusters (Held-Karp extended to clusters).
/// Throws std::invalid_argument when there are more than kGtspExactMaxClusters clusters.
GtspTour solveGtspExact(const GtspInstance& g);

/// Heuristic: greedy construction, then 2-opt and or-opt on the cluster order, each order scored
/// with its optimal candidate choice (a shortest path through the layered candidate graph).
GtspTour solveGtspHeuristic(const GtspInstance& g);

/// Exact for up to `exact_max_clusters` clusters, heuristic beyond.
GtspTour solveGtsp(const GtspInstance& g, int exact_max_clusters = 8);

}  // namespace wattswath::planner
