#pragma once
/// @file polygon.hpp
/// Plain value types for survey areas in a local East-North-Up metric frame.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace wattswath::geometry {

/// A point in the local ENU frame [m] (x east, y north).
using Point = Eigen::Vector2d;

/// A closed ring of vertices without the repeated closing vertex [m].
using Ring = std::vector<Point>;

/// A polygon with holes: the outer boundary counter-clockwise, holes clockwise [m].
struct PolygonWithHoles {
  Ring outer;               ///< outer boundary, counter-clockwise
  std::vector<Ring> holes;  ///< holes / no-fly zones inside, clockwise
};

/// Signed area of a ring (positive when counter-clockwise) [m^2].
double signedArea(const Ring& ring);

/// Area of the polygon minus its holes [m^2].
double area(const PolygonWithHoles& poly);

/// [m] The minimum width of `ring`: the narrowest strip between two parallel lines that holds
/// every vertex (CGAL::min_strip_2 on the convex hull); 0 for fewer than 3 distinct points. No
/// sweep direction crosses the ring with fewer than width / spacing lines.
double minimumWidth(const Ring& ring);

}  // namespace wattswath::geometry
