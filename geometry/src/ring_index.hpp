#pragma once
// The edges of a large ring in an R-tree (Boost.Geometry), for the questions a route search asks
// thousands of times: where a segment crosses the ring, whether a point is inside, whether an edge
// is within a distance; and an area's many holes by bounding box, for whether a segment enters one. Each answer applies the same test as the plain loops of check.cpp and
// containment.cpp, to the edges whose bounding boxes can matter instead of to every edge.
#include <vector>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::geometry::detail {

/// Rings with fewer vertices than this are answered by the plain loops (exactly as before; the
/// index would not pay for itself).
inline constexpr std::size_t kMinIndexedVertices = 64;

/// A ring's edges (i, i + 1) by bounding box.
class RingIndex {
 public:
  /// Indexes the edges of `ring` (kept by reference: it must outlive the index).
  explicit RingIndex(const Ring& ring);

  /// insideRing(ring, p) (even-odd, no margin), from the edges a ray to +x can cross.
  bool inside(const Point& p) const;
  /// distanceToRing(ring, p) <= d, from the edges whose boxes come within d.
  bool near(const Point& p, double d) const;
  /// The crossing parameters along a-b of the edges whose boxes meet the segment's (as
  /// crossingParams in containment.cpp; a parallel edge whose box misses the segment's adds no
  /// split: it could only split a piece that lies wholly on one side).
  void crossingParams(const Point& a, const Point& b, std::vector<double>& ts) const;
  /// The indexed ring.
  const Ring& ring() const { return ring_; }

 private:
  using BgPoint = boost::geometry::model::point<double, 2, boost::geometry::cs::cartesian>;
  using Box = boost::geometry::model::box<BgPoint>;
  using Value = std::pair<Box, std::size_t>;
  template <class F>
  void forEdgesIn(const Box& query, F f) const;

  const Ring& ring_;
  boost::geometry::index::rtree<Value, boost::geometry::index::rstar<16>> tree_;
};

/// The parameters t along a-b where it crosses edge p-(p + e), added to `ts` (the test of one edge
/// of crossingParams; shared by the plain loop and the index).
void edgeCrossing(const Point& a, const Point& b, const Point& p, const Point& e, std::vector<double>& ts);

/// segmentLeavesArea on the outer ring `outer` indexed.
bool segmentLeavesRing(const RingIndex& outer, const Point& a, const Point& b);

/// Areas with fewer holes than this are answered by the plain loop over the holes.
inline constexpr std::size_t kMinIndexedHoles = 16;

/// Whether segment a-b enters hole `hole` (the test segmentEntersHole applies to each hole).
bool segmentEntersRing(const Ring& hole, const Point& a, const Point& b);

/// An area's holes by bounding box: segmentEntersHole tests only the holes whose boxes meet the
/// segment's.
class HoleIndex {
 public:
  /// Indexes `holes` (kept by reference: they must outlive the index).
  explicit HoleIndex(const std::vector<Ring>& holes);
  /// segmentEntersHole(area with these holes, a, b).
  bool segmentEnters(const Point& a, const Point& b) const;

 private:
  using BgPoint = boost::geometry::model::point<double, 2, boost::geometry::cs::cartesian>;
  using Box = boost::geometry::model::box<BgPoint>;
  using Value = std::pair<Box, std::size_t>;
  const std::vector<Ring>& holes_;
  boost::geometry::index::rtree<Value, boost::geometry::index::rstar<16>> tree_;
};

}  // namespace wattswath::geometry::detail
