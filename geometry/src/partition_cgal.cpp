// CGAL translation unit: convex partitions of simple polygons (CGAL 2D Polygon Partitioning).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>

#include <cmath>
#include <iterator>
#include <list>
#include <stdexcept>
#include <string>

#include "wattswath/geometry/coverage.hpp"
#include "wattswath/geometry/polygon.hpp"
#include "wattswath/geometry/tolerances.hpp"

namespace wattswath::geometry {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Partition_traits_2<K>;
using CgalPolygon = Traits::Polygon_2;

constexpr std::size_t kMaxOptimalVertices = 24;  // Greene's optimal partition is O(n^4): beyond, Hertel-Mehlhorn

}  // namespace

std::vector<Ring> convexPartition(const Ring& ring) {
  // Drop repeated and collinear vertices: CGAL's partitions need a simple polygon, and a straight
  // vertex would only add a piece boundary nobody needs.
  Ring r;
  for (const auto& p : ring) {
    if (!p.allFinite()) throw std::invalid_argument("convexPartition: a vertex is not finite");
    if (r.empty() || (p - r.back()).norm() > tol::kPosition) r.push_back(p);
  }
  while (r.size() > 1 && (r.front() - r.back()).norm() <= tol::kPosition) r.pop_back();
  for (bool changed = true; changed && r.size() > 3;) {
    changed = false;
    for (std::size_t i = 0; i < r.size() && r.size() > 3; ++i) {
      const Point& a = r[(i + r.size() - 1) % r.size()];
      const Point& b = r[i];
      const Point& c = r[(i + 1) % r.size()];
      const Point u = b - a, v = c - b;
      if (std::abs(u.x() * v.y() - u.y() * v.x()) <= tol::kPosition * (u.norm() + v.norm())) {
        r.erase(r.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        break;
      }
    }
  }
  if (r.size() == 3 && std::abs(signedArea(r)) <= tol::kPosition * tol::kPosition) r.pop_back();  // collinear triple
  if (r.size() < 3) throw std::invalid_argument("convexPartition: " + std::to_string(r.size()) +
                                                " distinct non-collinear vertices (at least 3 expected)");
  CgalPolygon poly;
  for (const auto& p : r) poly.push_back(Traits::Point_2(p.x(), p.y()));
  if (!poly.is_simple()) throw std::invalid_argument("convexPartition: the ring is not simple (it crosses itself)");
  if (poly.orientation() != CGAL::COUNTERCLOCKWISE) poly.reverse_orientation();
  std::vector<Ring> out;
  if (poly.is_convex()) {
    Ring piece;
    for (auto v = poly.vertices_begin(); v != poly.vertices_end(); ++v) piece.emplace_back(v->x(), v->y());
    out.push_back(std::move(piece));
    return out;
  }
  std::list<CgalPolygon> parts;
  if (poly.size() <= kMaxOptimalVertices) {
    CGAL::optimal_convex_partition_2(poly.vertices_begin(), poly.vertices_end(), std::back_inserter(parts));
  } else {
    CGAL::approx_convex_partition_2(poly.vertices_begin(), poly.vertices_end(), std::back_inserter(parts));
  }
  for (const auto& part : parts) {
    Ring piece;
    for (auto v = part.vertices_begin(); v != part.vertices_end(); ++v) piece.emplace_back(v->x(), v->y());
    out.push_back(std::move(piece));
  }
  return out;
}

}  // namespace wattswath::geometry
