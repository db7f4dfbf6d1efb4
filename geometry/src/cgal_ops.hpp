#pragma once
// Private to geometry/src: the CGAL operations behind coverage.cpp and check.cpp, with our own
// value types at the interface so only decompose_cgal.cpp and check_cgal.cpp include CGAL.
#include <memory>
#include <utility>
#include <vector>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::geometry::detail {

/// The area outside the holes as CGAL's Boolean set operations see it (outer minus each hole),
/// split into polygons with holes (outer CCW, holes CW). Handles holes touching the boundary.
std::vector<PolygonWithHoles> regularizedRegions(const PolygonWithHoles& area);

/// Union of the Minkowski sums of each ring with the regular `sides`-gon of circumradius
/// `circumradius` [m] centred on the origin: outer boundaries, counter-clockwise. Throws
/// std::invalid_argument naming the ring when one is not a simple polygon.
std::vector<Ring> minkowskiUnion(const std::vector<Ring>& rings, double circumradius, int sides);

/// Convex pieces with vertical walls covering `poly` (CGAL::Polygon_vertical_decomposition_2).
std::vector<Ring> verticalDecomposition(const PolygonWithHoles& poly);

/// Interior straight skeleton of a simple ring, built once, offset at any distance.
class InwardOffsetter {
 public:
  /// Builds the skeleton of `ring` (ok() is false when CGAL cannot, e.g. a non-simple ring).
  explicit InwardOffsetter(const Ring& ring);
  /// Whether the skeleton was built.
  bool ok() const;
  /// Offset rings (CCW) at inward distance `offset` [m]; empty when nothing remains.
  std::vector<Ring> at(double offset) const;
  /// Points along the inner skeleton edges, at most `step` [m] apart, with their offset time
  /// (depth) [m], linear along each edge.
  std::vector<std::pair<Point, double>> depthSamples(double step) const;
  /// Largest offset time (the depth of the deepest point) [m].
  double depth() const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

/// Area of (union of `swaths`) intersected with `area` [m^2].
double coveredArea(const PolygonWithHoles& area, const std::vector<Ring>& swaths);

}  // namespace wattswath::geometry::detail
