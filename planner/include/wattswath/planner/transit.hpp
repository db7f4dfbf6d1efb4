#pragma once
/// @file transit.hpp
/// Transits around no-fly zones: the exact shortest path among polygonal obstacles, from a
/// visibility graph over the obstacles' vertices pushed out by a clearance (Boost.Graph Dijkstra).

#include <memory>
#include <utility>
#include <vector>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::planner {

/// Settings of the transit router.
struct TransitSettings {
  double clearance = 2.0;  ///< [m] distance kept from obstacle vertices, (0, 100]
};

/// Whether the open segment a-b enters the interior of `ring` (touching its boundary is allowed).
bool segmentEntersRing(const geometry::Point& a, const geometry::Point& b, const geometry::Ring& ring);

/// Shortest collision-free polylines between points among fixed polygonal obstacles.
class TransitRouter {
 public:
  /// Router around `obstacles` (rings of any orientation, e.g. holes and no-fly zones) [m].
  /// Throws std::invalid_argument when a ring has fewer than 3 vertices or settings are out of range.
  explicit TransitRouter(std::vector<geometry::Ring> obstacles, TransitSettings settings = {});
  ~TransitRouter();
  TransitRouter(TransitRouter&&) noexcept;
  TransitRouter& operator=(TransitRouter&&) noexcept;

  /// Shortest polyline from `a` to `b` avoiding the obstacles (both end points included) [m].
  /// When `a` or `b` lies inside an obstacle, or no route exists, throws std::runtime_error
  /// naming the point.
  std::vector<geometry::Point> route(const geometry::Point& a, const geometry::Point& b) const;
  /// Shortest polylines between all pairs of `points` [m]: element [i * n + j] for i < j is the
  /// route from points[i] to points[j] (as route()); the others are empty. Each point's view of
  /// the obstacle vertices is computed once. Throws like route().
  std::vector<std::vector<geometry::Point>> routeAll(const std::vector<geometry::Point>& points) const;
  /// Whether the straight segment a-b avoids every obstacle.
  bool clear(const geometry::Point& a, const geometry::Point& b) const;
  /// Whether `p` lies inside an obstacle.
  bool blocked(const geometry::Point& p) const;
  /// The obstacles.
  const std::vector<geometry::Ring>& obstacles() const;

 private:
  std::vector<std::pair<size_t, double>> visibleNodes(const geometry::Point& p) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace wattswath::planner
