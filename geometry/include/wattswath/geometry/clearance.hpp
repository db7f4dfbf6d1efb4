#pragma once
/// @file clearance.hpp
/// Keeping clear: rings grown by a margin (no-fly zones inflated for GPS and tracking error, an
/// area's boundary grown into a geofence), an area minus such rings, and the checker that reports
/// every leg of a path that comes closer to a zone than the margin or leaves a fence.

#include <vector>

#include "wattswath/geometry/path.hpp"
#include "wattswath/geometry/polygon.hpp"

namespace wattswath::geometry {

/// [-] Sides of the regular polygon that stands for the disk when rings are inflated.
inline constexpr int kInflateSides = 16;

/// `rings` grown outwards by `distance` [m] (> 0) and merged where they overlap: the Minkowski sum
/// of each ring with a regular `sides`-gon circumscribing the disk of radius `distance` (CGAL, exact),
/// then their union. Every point within `distance` of a ring is inside the result; no point of the
/// result is farther than distance / cos(pi / sides) from one. Outer boundaries only, counter-clockwise
/// (a pocket enclosed by the union is dropped: it cannot be reached). Throws std::invalid_argument
/// for a non-positive or non-finite distance, fewer than 3 sides or a ring that is not simple.
std::vector<Ring> inflateRings(const std::vector<Ring>& rings, double distance, int sides = kInflateSides);

/// The parts of the polygon `outer` [m] outside every ring of `cut` (CGAL Boolean difference): outer
/// boundaries counter-clockwise, holes clockwise. Rings of `cut` may cross `outer` or overlap.
std::vector<PolygonWithHoles> subtractRings(const Ring& outer, const std::vector<Ring>& cut);

/// Smallest distance [m] between `leg` (a line, an arc, or a turn in place's point) and the boundary
/// of `ring`; 0 when the leg touches or crosses it.
double distanceToRing(const PathLeg& leg, const Ring& ring);

/// A leg that does not keep its margin.
struct MarginViolation {
  int leg = -1;             ///< [-] index of the leg in the path
  int zone = -1;            ///< [-] index of the ring it comes too close to
  double distance_m = 0.0;  ///< [m] distance to that ring's boundary (0 when the leg enters or crosses it)
};

/// Every leg of `path` that comes closer than `margin` [m] to a ring of `zones` or lies inside one
/// (exact distances: lines, arcs, points of turns in place, to the rings' edges). Empty when every
/// flown point keeps the margin.
std::vector<MarginViolation> marginViolations(const CoveragePath& path, const std::vector<Ring>& zones,
                                              double margin);

/// Every leg of `path` that leaves `fence` [m] or comes closer than `margin` [m] to its boundary
/// (zone 0). Empty when every flown point is at least `margin` inside the fence.
std::vector<MarginViolation> fenceViolations(const CoveragePath& path, const Ring& fence, double margin);

}  // namespace wattswath::geometry
