// CGAL translation unit (slow to compile): Boolean set operations for the coverage checker.
#include <stdexcept>
#include <string>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include "cgal_ops.hpp"

namespace wattswath::geometry::detail {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using EPolygon = CGAL::Polygon_2<EK>;
using EPolygonWithHoles = CGAL::Polygon_with_holes_2<EK>;

EPolygon toExact(const Ring& r) {
  EPolygon p;
  for (const auto& v : r) p.push_back(EK::Point_2(v.x(), v.y()));
  if (p.size() >= 3 && p.orientation() != CGAL::COUNTERCLOCKWISE) p.reverse_orientation();
  return p;
}

double areaOf(const CGAL::Polygon_set_2<EK>& set) {
  std::vector<EPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  double a = 0.0;
  for (const auto& pwh : parts) {
    a += CGAL::to_double(pwh.outer_boundary().area());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) a -= std::abs(CGAL::to_double(h->area()));
  }
  return a;
}

}  // namespace

double coveredArea(const PolygonWithHoles& area, const std::vector<Ring>& swaths) {
  std::vector<EPolygon> polys;
  polys.reserve(swaths.size());
  for (const auto& s : swaths) {
    EPolygon p = toExact(s);
    if (p.size() >= 3 && p.is_simple() && p.area() != 0) polys.push_back(std::move(p));
  }
  if (polys.empty()) return 0.0;
  // CGAL checks simplicity only as a precondition, which Release builds compile out (a repeated
  // vertex then gives a wrong area, not an error): check it here.
  const EPolygon outer = toExact(area.outer);
  if (outer.size() < 3 || !outer.is_simple())
    throw std::invalid_argument("coverage check: the area's outer boundary is not a simple polygon (" +
                                std::to_string(area.outer.size()) + " vertices; repeated vertex or self-intersection)");
  CGAL::Polygon_set_2<EK> covered;
  covered.join(polys.begin(), polys.end());
  CGAL::Polygon_set_2<EK> region(outer);
  for (size_t i = 0; i < area.holes.size(); ++i) {
    const EPolygon h = toExact(area.holes[i]);
    if (h.size() < 3 || !h.is_simple())
      throw std::invalid_argument("coverage check: hole " + std::to_string(i) +
                                  " is not a simple polygon (repeated vertex or self-intersection)");
    region.difference(h);
  }
  covered.intersection(region);
  return areaOf(covered);
}

}  // namespace wattswath::geometry::detail
