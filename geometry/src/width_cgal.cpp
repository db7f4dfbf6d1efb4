// The minimum width of a ring (CGAL's minimum enclosing strip of its convex hull).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/min_quadrilateral_2.h>

#include <cmath>
#include <iterator>
#include <vector>

#include "wattswath/geometry/polygon.hpp"

namespace wattswath::geometry {

double minimumWidth(const Ring& ring) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_2> pts, hull;
  for (const auto& p : ring)
    if (p.allFinite()) pts.emplace_back(p.x(), p.y());
  CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(hull));
  if (hull.size() < 3) return 0.0;
  std::vector<K::Line_2> strip;
  CGAL::min_strip_2(hull.begin(), hull.end(), std::back_inserter(strip));
  if (strip.size() != 2) return 0.0;
  return std::sqrt(CGAL::squared_distance(strip[0].point(0), strip[1]));
}

}  // namespace wattswath::geometry
