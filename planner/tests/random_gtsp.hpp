#pragma once
// Random Euclidean GTSP instances for the cell-order tests and benchmarks: each candidate has an
// entry and an exit point near its cluster's centre, so transits are asymmetric.
#include <random>
#include <vector>

#include "wattswath/planner/order.hpp"

namespace wattswath::planner {

/// `clusters` clusters of `per` candidates in a `side` m square (fixed `seed`), internal costs
/// 10..50, transits `scale` x the distance from a candidate's exit to the next one's entry; the
/// depot at the origin.
inline GtspInstance randomGtspInstance(int clusters, int per, unsigned seed, double side = 100.0, double scale = 1.7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, side), du(-0.05 * side, 0.05 * side), cu(10.0, 50.0);
  GtspInstance g;
  std::vector<Eigen::Vector2d> entry, exit;
  for (int c = 0; c < clusters; ++c) {
    const Eigen::Vector2d centre(u(rng), u(rng));
    for (int k = 0; k < per; ++k) {
      g.cluster.push_back(c);
      g.cost.push_back(cu(rng));
      entry.push_back(centre + Eigen::Vector2d(du(rng), du(rng)));
      exit.push_back(centre + Eigen::Vector2d(du(rng), du(rng)));
    }
  }
  entry.push_back({0, 0});
  exit.push_back({0, 0});
  const int n = static_cast<int>(entry.size());
  g.transit.resize(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) g.transit(i, j) = (exit[i] - entry[j]).norm() * scale;
  return g;
}

}  // namespace wattswath::planner
