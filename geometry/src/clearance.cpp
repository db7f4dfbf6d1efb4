// Keeping clear: rings inflated by a margin and an area minus rings (CGAL behind cgal_ops.hpp), and
// the exact distance between a path's legs (lines, arcs, points) and a ring's edges.
#include "wattswath/geometry/clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cgal_ops.hpp"
#include "wattswath/geometry/check.hpp"

namespace wattswath::geometry {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

/// 2-D cross product of `a` and `b`.
double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Whether the closed segments a-b and c-d share a point.
bool segmentsMeet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return distanceToSegment(c, a, b) == 0.0 || distanceToSegment(d, a, b) == 0.0 || distanceToSegment(a, c, d) == 0.0 ||
         distanceToSegment(b, c, d) == 0.0;
}

double segmentToSegment(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (segmentsMeet(a, b, c, d)) return 0.0;
  return std::min({distanceToSegment(a, c, d), distanceToSegment(b, c, d), distanceToSegment(c, a, b),
                   distanceToSegment(d, a, b)});
}

/// Whether direction `phi` [rad] from the centre lies on the arc `leg` (start angle, signed sweep).
bool onArc(const PathLeg& leg, double phi) {
  if (std::abs(leg.turn_angle) >= kTwoPi) return true;
  const double a0 = std::atan2(leg.start.y() - leg.center.y(), leg.start.x() - leg.center.x());
  double delta = std::fmod(phi - a0, kTwoPi);
  if (leg.turn_angle >= 0) {
    if (delta < 0) delta += kTwoPi;
    return delta <= leg.turn_angle;
  }
  if (delta > 0) delta -= kTwoPi;
  return delta >= leg.turn_angle;
}

double pointToArc(const Point& p, const PathLeg& leg) {
  const Point v = p - leg.center;
  const double r = v.norm();
  if (r > 0.0 && onArc(leg, std::atan2(v.y(), v.x()))) return std::abs(r - leg.radius);
  return std::min((p - leg.start).norm(), (p - leg.end).norm());
}

/// Exact distance between the arc `leg` and the segment a-b: 0 where they meet, else the least of
/// the ends' distances and the arc point nearest the segment's line (its radial through the foot).
double arcToSegment(const PathLeg& leg, const Point& a, const Point& b) {
  const Point d = b - a, f = a - leg.center;
  const double dd = d.squaredNorm();
  if (dd > 0.0) {
    const double half_b = f.dot(d), c = f.squaredNorm() - leg.radius * leg.radius, disc = half_b * half_b - dd * c;
    if (disc >= 0.0)
      for (double t : {(-half_b - std::sqrt(disc)) / dd, (-half_b + std::sqrt(disc)) / dd}) {
        const Point q = f + t * d;
        if (t >= 0.0 && t <= 1.0 && onArc(leg, std::atan2(q.y(), q.x()))) return 0.0;
      }
  }
  double best = std::min({pointToArc(a, leg), pointToArc(b, leg), distanceToSegment(leg.start, a, b),
                          distanceToSegment(leg.end, a, b)});
  const double t = dd > 0.0 ? -f.dot(d) / dd : 0.0;
  const Point foot = f + t * d;  // relative to the centre
  if (dd > 0.0 && t > 0.0 && t < 1.0 && foot.norm() > 0.0 && onArc(leg, std::atan2(foot.y(), foot.x())))
    best = std::min(best, std::abs(foot.norm() - leg.radius));
  return best;
}

double legToSegment(const PathLeg& leg, const Point& a, const Point& b) {
  switch (leg.kind) {
    case PrimitiveKind::Line: return segmentToSegment(leg.start, leg.end, a, b);
    case PrimitiveKind::Arc: return arcToSegment(leg, a, b);
    case PrimitiveKind::TurnInPlace: return distanceToSegment(leg.start, a, b);
  }
  return 0.0;
}

}  // namespace

std::vector<Ring> inflateRings(const std::vector<Ring>& rings, double distance, int sides) {
  if (!(std::isfinite(distance) && distance > 0.0))
    throw std::invalid_argument("inflateRings: distance = " + std::to_string(distance) + " m, expected > 0");
  if (sides < 3) throw std::invalid_argument("inflateRings: sides = " + std::to_string(sides) + ", expected >= 3");
  try {
    return detail::minkowskiUnion(rings, distance / std::cos(M_PI / sides), sides);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("inflateRings: ") + e.what());
  }
}

std::vector<PolygonWithHoles> subtractRings(const Ring& outer, const std::vector<Ring>& cut) {
  return detail::regularizedRegions(PolygonWithHoles{outer, cut});
}

double distanceToRing(const PathLeg& leg, const Ring& ring) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < ring.size() && best > 0.0; ++i)
    best = std::min(best, legToSegment(leg, ring[i], ring[(i + 1) % ring.size()]));
  return best;
}

std::vector<MarginViolation> marginViolations(const CoveragePath& path, const std::vector<Ring>& zones, double margin) {
  std::vector<MarginViolation> out;
  for (size_t i = 0; i < path.legs.size(); ++i)
    for (size_t z = 0; z < zones.size(); ++z) {
      if (zones[z].size() < 3) continue;
      const double d = insideRing(zones[z], path.legs[i].start) ? 0.0 : distanceToRing(path.legs[i], zones[z]);
      if (d < margin) out.push_back({static_cast<int>(i), static_cast<int>(z), d});
    }
  return out;
}

std::vector<MarginViolation> fenceViolations(const CoveragePath& path, const Ring& fence, double margin) {
  std::vector<MarginViolation> out;
  for (size_t i = 0; i < path.legs.size(); ++i) {
    const double d = insideRing(fence, path.legs[i].start) ? distanceToRing(path.legs[i], fence) : 0.0;
    if (d < margin) out.push_back({static_cast<int>(i), 0, d});
  }
  return out;
}

}  // namespace wattswath::geometry
