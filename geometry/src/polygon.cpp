#include "wattswath/geometry/polygon.hpp"

#include <cmath>

namespace wattswath::geometry {

double signedArea(const Ring& ring) {
  double a = 0.0;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % n];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

double area(const PolygonWithHoles& poly) {
  double a = std::abs(signedArea(poly.outer));
  for (const auto& h : poly.holes) a -= std::abs(signedArea(h));
  return a;
}

}  // namespace wattswath::geometry
