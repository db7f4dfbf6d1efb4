#pragma once
/// @file check.hpp
/// Validity checkers reused by the tests and the planner: how much of an area a path's swaths
/// cover (CGAL Boolean operations), and what is wrong with a path (empty list = valid).

#include <string>
#include <vector>

#include "wattswath/geometry/path.hpp"
#include "wattswath/geometry/tolerances.hpp"

namespace wattswath::geometry {

/// Area covered by a set of paths over the area outside the holes.
struct CoverageReport {
  double required_area = 0.0;  ///< [m^2] area of the polygon minus its holes
  double covered_area = 0.0;   ///< [m^2] part of it inside the union of the swaths
  /// Covered over required [-] (1 when nothing is required).
  double fraction() const { return required_area > 0.0 ? covered_area / required_area : 1.0; }
};

/// Swath polygons of `path`: for every Sweep or Turn leg a square camera footprint of side
/// `spacing` [m] swept along it (lines: a rectangle reaching spacing/2 beyond each end; arcs: one
/// such rectangle per chord of at most tol::kSwathArcChord). Turns in place add nothing.
std::vector<Ring> swathPolygons(const CoveragePath& path, double spacing);

/// Union of the swaths of all `paths` intersected with `area`, over the area (CGAL Boolean set
/// operations on exact coordinates).
CoverageReport checkCoverage(const PolygonWithHoles& area, const std::vector<CoveragePath>& paths, double spacing);

/// Problems of a path (empty = ok): a gap or heading jump between legs, an arc whose ends are not
/// on its circle or whose headings are not tangent, a line whose headings are not along it, a
/// non-finite value, a leg that enters a hole of `area` deeper than tol::kHoleDepth.
std::vector<std::string> checkPath(const CoveragePath& path, const PolygonWithHoles& area);

/// How much of a path lies where it must not: outside the area's outer boundary or inside a hole.
struct ContainmentReport {
  double outside_m = 0.0;    ///< [m] length flown outside the outer boundary
  double in_holes_m = 0.0;   ///< [m] length flown inside a hole (no-fly zone)
  double max_depth_m = 0.0;  ///< [m] farthest a flown point gets beyond the boundary it crosses
  /// Length outside plus length in holes [m].
  double total() const { return outside_m + in_holes_m; }
};
/// Length of `path` outside `area` and inside its holes: lines cut exactly at every boundary
/// crossing, arcs as chords of at most tol::kArcChord; a piece within `tolerance` [m] of the
/// boundary counts as inside. With `survey_only` the legs before the first sweep and after the
/// last one (the approach from home and the return, home may lie outside) are left out.
ContainmentReport checkContainment(const PolygonWithHoles& area, const CoveragePath& path, bool survey_only = true,
                                   double tolerance = tol::kContainment);
/// Whether the segment from `a` to `b` [m] enters the interior of any hole of `area` (touching or
/// running along a hole's boundary is allowed).
bool segmentEntersHole(const PolygonWithHoles& area, const Point& a, const Point& b);

/// Whether the segment from `a` to `b` [m] runs outside the outer boundary of `area` (farther than
/// tol::kContainment from it).
bool segmentLeavesArea(const PolygonWithHoles& area, const Point& a, const Point& b);
/// Shortest polyline from `a` to `b` [m] that enters no hole, over the holes' convex vertices and
/// the outer boundary's reflex ones (visibility graph, A* with lazy edge checks); includes both ends. When both
/// ends lie inside the outer boundary the route stays inside it; otherwise (a transit from home
/// outside) it only avoids the holes.
std::vector<Point> safeRoute(const PolygonWithHoles& area, const Point& a, const Point& b);

/// Whether `p` [m] lies strictly inside `ring` by more than `margin` [m] (even-odd rule).
bool insideRing(const Ring& ring, const Point& p, double margin = 0.0);

/// Distance from `p` to the segment from `a` to `b` [m] (to `a` when the segment has no length).
double distanceToSegment(const Point& p, const Point& a, const Point& b);
/// Distance from `p` to the nearest edge of the closed `ring` [m] (infinity for an empty ring).
double distanceToRing(const Ring& ring, const Point& p);

}  // namespace wattswath::geometry
